// SPDX-License-Identifier: MIT
// The membrane's power balance over a time window: the work the fluid's force did on it against its dissipation and
// the change of its stored (elastic + kinetic) energy, from the npFEM energy books (NpfemStatistics).
#pragma once

#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

/// The running energy books of a membrane (sums since the start) and its stored energies, at one instant. Joules.
struct MembraneEnergySnapshot {
  double time_s = 0.0;
  double external_work_J = 0.0;         // NpfemStatistics sums ...
  double viscous_dissipation_J = 0.0;
  double damping_dissipation_J = 0.0;
  double elastic_work_J = 0.0;
  double kinetic_step_loss_J = 0.0;
  double solver_residual_work_J = 0.0;
  double elastic_energy_J = 0.0;        // ... and the state: E(x) (one energy evaluation) and sum m |v|^2 / 2
  double kinetic_energy_J = 0.0;
};

[[nodiscard]] MembraneEnergySnapshot membrane_energy_snapshot(const NpfemSolver& membrane, double time_s);

/// The balance over [a, b]. Physically the work the fluid gives the membrane is dissipated by its viscosity (and the
/// small Rayleigh damping) or stored: balance_residual = fluid_work - viscous - damping - dE - dKE. The implicit
/// Euler step adds its own loss (implicit_step_loss = M|dv|^2 / 2 + grad E(x_{n+1}).u - dE, O(h) relative; of either
/// sign, as E is not convex in x) and an unconverged minimisation leaves solver_residual_work; books_error =
/// balance_residual - those two is round-off for a free membrane without the friction (NpfemStatistics).
struct MembraneEnergyBalance {
  double duration_s = 0.0;
  double fluid_work_J = 0.0;
  double viscous_dissipation_J = 0.0;
  double damping_dissipation_J = 0.0;
  double elastic_energy_change_J = 0.0;
  double kinetic_energy_change_J = 0.0;
  double implicit_step_loss_J = 0.0;
  double solver_residual_work_J = 0.0;
  double balance_residual_J = 0.0;
  double books_error_J = 0.0;
  /// balance_residual / fluid_work (0 when no work was done).
  [[nodiscard]] double relative_residual() const {
    return fluid_work_J != 0.0 ? balance_residual_J / fluid_work_J : 0.0;
  }
  /// Mean powers over the window, watts.
  [[nodiscard]] double mean_fluid_power_W() const { return duration_s > 0.0 ? fluid_work_J / duration_s : 0.0; }
  [[nodiscard]] double mean_viscous_power_W() const {
    return duration_s > 0.0 ? viscous_dissipation_J / duration_s : 0.0;
  }
};

[[nodiscard]] MembraneEnergyBalance membrane_energy_balance(const MembraneEnergySnapshot& a,
                                                            const MembraneEnergySnapshot& b);

}  // namespace hs::resolved
