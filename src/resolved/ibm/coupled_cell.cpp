// SPDX-License-Identifier: MIT
// One membrane immersed in the lattice fluid: the coupled time step of Palabos-npFEM (resolved-methods.md 2.3).
#include "resolved/ibm/coupled_cell.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "common/errors.hpp"

namespace hs::resolved {

CoupledCell::CoupledCell(FluidLattice& lattice, NpfemSolver& membrane, const common::UnitConverter& units,
                         const CouplingSettings& settings)
    : lattice_(lattice), membrane_(membrane), units_(units), settings_(settings), ibm_(lattice, settings.ibm) {
  if (settings_.membrane_every < 1) throw std::invalid_argument("membrane_every must be >= 1");
  const double h_expected = settings_.membrane_every * units_.dt_s();
  if (std::abs(membrane_.time_step_s() - h_expected) > 1e-9 * h_expected) {
    throw std::invalid_argument("the membrane time step must be membrane_every * dt");
  }
  if (settings_.median_filter) ring_ = one_ring(membrane_.vertex_count(), membrane_.triangles());
  // The reaction balances the impulses exactly; the npFEM step must then not create momentum of its own.
  if (settings_.membrane_force == MembraneForce::ibm_reaction) membrane_.set_exact_translation(true);
  markers_.x_lu = membrane_positions_lu();
  markers_.u_lu.assign(markers_.x_lu.size(), {});
  const auto v = membrane_.velocities_m_s();
  for (std::size_t k = 0; k < v.size(); ++k) {
    for (int a = 0; a < 3; ++a) markers_.u_lu[k][a] = units_.to_lattice_velocity(v[k][a]);
  }
  markers_.area_lu.assign(markers_.x_lu.size(), 0.0);
}

std::vector<common::Vec3> CoupledCell::membrane_positions_lu() const {
  auto x = membrane_.positions_m();
  for (auto& p : x) p = (p - settings_.lattice_origin_m) / units_.dx_m();
  return x;
}

std::vector<common::Vec3> CoupledCell::marker_positions_m() const {
  std::vector<common::Vec3> x = markers_.x_lu;
  for (auto& p : x) p = settings_.lattice_origin_m + units_.dx_m() * p;
  return x;
}

std::vector<common::Vec3> CoupledCell::stress_force_N() {
  const auto normals = membrane_.vertex_normals();
  const TractionResult t = fluid_traction(ibm_, lattice_, {markers_.x_lu, normals, markers_.area_lu, membrane_.triangles()},
                                        ring_, settings_.traction_area);
  std::vector<common::Vec3> f_N(t.force_lu.size());
  report_.fluid_force_N = {};
  const bool add_drive = settings_.drive_on_enclosed_volume && !t.enclosed_volume_lu.empty();
  for (std::size_t k = 0; k < f_N.size(); ++k) {
    for (int a = 0; a < 3; ++a) f_N[k][a] = units_.to_si_force(t.force_lu[k][a]);
    report_.fluid_force_N += f_N[k];   // the traction alone
    if (!add_drive) continue;
    const common::Vec3 drive_lu = t.enclosed_volume_lu[k] * lattice_.body_force();
    for (int a = 0; a < 3; ++a) f_N[k][a] += units_.to_si_force(drive_lu[a]);
  }
  report_.vertices_without_fluid = t.vertices_without_fluid;
  report_.sample_distance_lu = t.mean_sample_distance_lu;
  return f_N;
}

/// The fluid received sum_n F_k^n dt (SI impulse) from marker k over the lattice steps n of the last interval; the
/// npFEM step applies its external force over h = k dt, so f_k = -sum_n F_k^n / k gives the membrane exactly minus
/// that impulse. The first interval (nothing spread yet) and a shorter one after a restart are covered too: the
/// division is by k, not by the number of steps summed, so the impulses always balance.
std::vector<common::Vec3> CoupledCell::reaction_force_N() {
  std::vector<common::Vec3> f_N(markers_.x_lu.size());
  report_.fluid_force_N = {};
  const double per_step = -1.0 / static_cast<double>(settings_.membrane_every);
  for (std::size_t k = 0; k < f_N.size() && k < reaction_lu_.size(); ++k) {
    for (int a = 0; a < 3; ++a) f_N[k][a] = units_.to_si_force(per_step * reaction_lu_[k][a]);
    report_.fluid_force_N += f_N[k];
  }
  reaction_lu_.assign(markers_.x_lu.size(), {});
  report_.vertices_without_fluid = 0;
  report_.sample_distance_lu = 0.0;
  return f_N;
}

void CoupledCell::membrane_solve() {
  const auto areas_m2 = membrane_.vertex_areas_m2();
  const double dx2 = units_.dx_m() * units_.dx_m();
  for (std::size_t k = 0; k < areas_m2.size(); ++k) markers_.area_lu[k] = areas_m2[k] / dx2;
  if (!interval_starts()) return;
  std::vector<common::Vec3> f_N =
      settings_.membrane_force == MembraneForce::ibm_reaction ? reaction_force_N() : stress_force_N();
  report_.fluid_forces_N = f_N;
  if (settings_.add_forces_N) settings_.add_forces_N(membrane_.positions_m(), f_N);
  membrane_.set_external_forces_N(f_N);
  membrane_.step();
  const auto v = membrane_.velocities_m_s();
  next_u_lu_.resize(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    for (int a = 0; a < 3; ++a) next_u_lu_[k][a] = units_.to_lattice_velocity(v[k][a]);
  }
}

void CoupledCell::ibm_forcing() { take_forcing(ibm_.apply(markers_)); }

void CoupledCell::take_forcing(ForcingReport forcing) {
  report_.forcing = std::move(forcing);
  if (settings_.membrane_force != MembraneForce::ibm_reaction) return;
  const auto& f = report_.forcing.marker_force_lu;
  if (reaction_lu_.size() != f.size()) reaction_lu_.assign(f.size(), {});
  for (std::size_t k = 0; k < f.size(); ++k) reaction_lu_[k] += f[k];
}

void CoupledCell::lbm_step() { lattice_.step(); }

void CoupledCell::markers_advect() {
  if (interval_starts()) markers_.u_lu = next_u_lu_;
  for (std::size_t k = 0; k < markers_.x_lu.size(); ++k) markers_.x_lu[k] += markers_.u_lu[k];
  ++steps_;
  if (interval_starts()) {   // the interval just ended: land exactly on the npFEM positions
    const auto target = membrane_positions_lu();
    double drift = 0.0;
    for (std::size_t k = 0; k < target.size(); ++k) drift = std::max(drift, common::norm(target[k] - markers_.x_lu[k]));
    report_.marker_drift_lu = drift;
    markers_.x_lu = target;
  }
}

void CoupledCell::step() {
  membrane_solve();
  ibm_forcing();
  lbm_step();
  markers_advect();
}

void CoupledCell::restore(const CouplingState& state) {
  ibm_.forget_forced_nodes();   // the lattice's force field was restored with it
  if (state.marker_x_lu.size() != markers_.x_lu.size() || state.marker_u_lu.size() != markers_.u_lu.size()) {
    throw std::invalid_argument("coupling checkpoint: marker count differs");
  }
  if (!state.reaction_lu.empty() && state.reaction_lu.size() != markers_.x_lu.size()) {
    throw std::invalid_argument("coupling checkpoint: reaction count differs");
  }
  markers_.x_lu = state.marker_x_lu;
  markers_.u_lu = state.marker_u_lu;
  steps_ = state.steps;
  reaction_lu_ = state.reaction_lu;   // empty (fluid_stress, or an older checkpoint): nothing pending
}

}  // namespace hs::resolved
