// SPDX-License-Identifier: MIT
// The membrane's power balance over a time window, from the npFEM energy books.
#include "resolved/membrane/membrane_energy_balance.hpp"

namespace hs::resolved {

MembraneEnergySnapshot membrane_energy_snapshot(const NpfemSolver& membrane, double time_s) {
  const NpfemStatistics& s = membrane.statistics();
  return {.time_s = time_s,
          .external_work_J = s.external_work_J,
          .viscous_dissipation_J = s.viscous_dissipation_J,
          .damping_dissipation_J = s.damping_dissipation_J,
          .elastic_work_J = s.elastic_work_J,
          .kinetic_step_loss_J = s.kinetic_step_loss_J,
          .solver_residual_work_J = s.solver_residual_work_J,
          .elastic_energy_J = membrane.elastic_energy_J(),
          .kinetic_energy_J = membrane.kinetic_energy_J()};
}

MembraneEnergyBalance membrane_energy_balance(const MembraneEnergySnapshot& a, const MembraneEnergySnapshot& b) {
  MembraneEnergyBalance r;
  r.duration_s = b.time_s - a.time_s;
  r.fluid_work_J = b.external_work_J - a.external_work_J;
  r.viscous_dissipation_J = b.viscous_dissipation_J - a.viscous_dissipation_J;
  r.damping_dissipation_J = b.damping_dissipation_J - a.damping_dissipation_J;
  r.elastic_energy_change_J = b.elastic_energy_J - a.elastic_energy_J;
  r.kinetic_energy_change_J = b.kinetic_energy_J - a.kinetic_energy_J;
  const double elastic_work = b.elastic_work_J - a.elastic_work_J;
  r.implicit_step_loss_J = (b.kinetic_step_loss_J - a.kinetic_step_loss_J) + (elastic_work - r.elastic_energy_change_J);
  r.solver_residual_work_J = b.solver_residual_work_J - a.solver_residual_work_J;
  r.balance_residual_J = r.fluid_work_J - r.viscous_dissipation_J - r.damping_dissipation_J -
                         r.elastic_energy_change_J - r.kinetic_energy_change_J;
  r.books_error_J = r.balance_residual_J - r.implicit_step_loss_J - r.solver_residual_work_J;
  return r;
}

}  // namespace hs::resolved
