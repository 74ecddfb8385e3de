// SPDX-License-Identifier: MIT
// Particle data as a structure of arrays: owned particles first, then ghost copies near block faces.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/vec3.hpp"

namespace hs::unresolved {

/// inlet_opening of particles not injected through an opening (volume insertion, a case's own placement).
inline constexpr std::int32_t no_inlet_opening = -1;

/// One particle as handed in by insertion or a case (SI units).
struct ParticleState {
  hs::common::Vec3 position_m;
  hs::common::Vec3 velocity_m_s;
  hs::common::Vec3 angular_velocity_rad_s;
  double radius_m = 0.0;
  double mass_kg = 0.0;
  std::int64_t id = 0;
  /// Index of the opening it entered through (OpeningTraffic); no_inlet_opening for a particle placed otherwise.
  std::int32_t inlet_opening = no_inlet_opening;
};

/// What a copy of another rank's particle carries besides its ParticleState: its owner's drag, fluid velocity and
/// external force (drag_limited_step() bounds the contact rates with them), kept in the ghost's own row.
struct GhostCoupling {
  double drag_N_s_m = 0.0;
  double rotational_drag_N_m_s = 0.0;
  hs::common::Vec3 fluid_velocity_m_s;
  hs::common::Vec3 external_force_N;
};

/// Structure of arrays. Indices [0, n_owned()) are the particles this block owns and integrates;
/// [n_owned(), size()) are ghosts: copies of particles (periodic images here, particles of neighbour blocks
/// once the run is distributed) that only take part in contacts. A ghost carries its owner's id; forces
/// computed on a ghost are added back to its owner by fold_ghost_forces() (the reverse halo exchange).
/// Per-particle coupling data (external force, drag coefficient, fluid velocity, drag impulse, lift, DI), the
/// opening a particle came in by and the wall-contact history live here too, so that sorting and (later) migration carry them along.
class ParticleStore {
 public:
  using Column = std::vector<double>;
  using Vec3Columns = std::array<Column, 3>;

  /// Appends an owned particle; removes all ghosts first.
  std::size_t add(const ParticleState& p);
  [[nodiscard]] ParticleState state(std::size_t i) const;

  [[nodiscard]] std::size_t n_owned() const { return n_owned_; }
  [[nodiscard]] std::size_t size() const { return id_.size(); }
  [[nodiscard]] std::size_t n_ghost() const { return size() - n_owned_; }

  // Kinematics and contact forces, owned + ghosts. Axis a = 0, 1, 2.
  Vec3Columns& position_m() { return pos_; }
  Vec3Columns& velocity_m_s() { return vel_; }
  Vec3Columns& angular_velocity_rad_s() { return omega_; }
  Vec3Columns& force_N() { return force_; }
  Vec3Columns& torque_Nm() { return torque_; }
  Column& radius_m() { return radius_; }
  Column& mass_kg() { return mass_; }
  std::vector<std::int64_t>& id() { return id_; }
  /// The opening each particle entered through (index into the run's openings), or no_inlet_opening.
  std::vector<std::int32_t>& inlet_opening() { return inlet_opening_; }
  const Vec3Columns& position_m() const { return pos_; }
  const Vec3Columns& velocity_m_s() const { return vel_; }
  const Vec3Columns& angular_velocity_rad_s() const { return omega_; }
  const Vec3Columns& force_N() const { return force_; }
  const Vec3Columns& torque_Nm() const { return torque_; }
  const Column& radius_m() const { return radius_; }
  const Column& mass_kg() const { return mass_; }
  const std::vector<std::int64_t>& id() const { return id_; }
  const std::vector<std::int32_t>& inlet_opening() const { return inlet_opening_; }

  // Coupling data (meaningful for owned particles).
  /// Constant external force and torque added every step until changed (fluid pressure, lift, gravity...).
  /// Asking for them writable switches the term on in the integrator (untouched, they cost no memory traffic).
  Vec3Columns& external_force_N() { external_used_ = true; return ext_force_; }
  Vec3Columns& external_torque_Nm() { external_used_ = true; return ext_torque_; }
  /// Linear drag beta (u_f - v), integrated exactly: beta in N s/m, u_f the fluid velocity at the particle.
  /// Asking for beta writable switches the exact-drag integrator on.
  Column& drag_coefficient_N_s_m() { drag_used_ = true; return drag_beta_; }
  [[nodiscard]] bool external_used() const { return external_used_; }
  [[nodiscard]] bool drag_used() const { return drag_used_; }
  Vec3Columns& fluid_velocity_m_s() { return fluid_vel_; }
  /// Rotational drag beta_r (Omega_f - w), integrated exactly like the linear drag (when drag_used()): beta_r in
  /// N m s (pi mu d^3 for a sphere in Stokes flow), Omega_f the fluid's angular velocity (half the vorticity) at the
  /// particle. Zero beta_r: no fluid torque. The fluid gets no reaction torque (CFDEM model A).
  Column& rotational_drag_N_m_s() { return rot_drag_; }
  Vec3Columns& fluid_angular_velocity_rad_s() { return fluid_omega_; }
  /// Drag impulse (N s) given to each particle since the coupling last zeroed it: the fluid gets minus this.
  Vec3Columns& drag_impulse_N_s() { return drag_impulse_; }
  /// Lift force of the current coupling step (N, part of the external force): the fluid gets minus this.
  Vec3Columns& lift_force_N() { return lift_; }
  /// Deformation index DI of the RBC each sphere stands for (set by the coupling's closures; output only).
  Column& deformation_index() { return di_; }
  /// Tangential spring of the particle-wall contact (m), zero when not touching the wall.
  Vec3Columns& wall_shear_m() { return wall_shear_; }
  const Vec3Columns& external_force_N() const { return ext_force_; }
  const Vec3Columns& external_torque_Nm() const { return ext_torque_; }
  const Column& drag_coefficient_N_s_m() const { return drag_beta_; }
  const Vec3Columns& fluid_velocity_m_s() const { return fluid_vel_; }
  const Column& rotational_drag_N_m_s() const { return rot_drag_; }
  const Vec3Columns& fluid_angular_velocity_rad_s() const { return fluid_omega_; }
  const Vec3Columns& drag_impulse_N_s() const { return drag_impulse_; }
  const Vec3Columns& lift_force_N() const { return lift_; }
  const Column& deformation_index() const { return di_; }
  const Vec3Columns& wall_shear_m() const { return wall_shear_; }

  /// Removes the owned particles i with remove[i] true (remove.size() == n_owned()); the others keep their order,
  /// ids, inlet openings and every column (forces, coupling data, wall history). Removes all ghosts first. Returns how many went.
  std::size_t remove_owned(const std::vector<bool>& remove);
  /// Reorders the owned particles: new particle k is old particle order[k]. Requires no ghosts.
  void permute_owned(const std::vector<std::size_t>& order);

  void clear_ghosts();
  /// Appends a ghost: a copy of owned particle `owner` displaced by `shift_m` (a periodic image).
  std::size_t add_ghost(std::size_t owner, const hs::common::Vec3& shift_m);
  /// ghost_owner() of a copy of another rank's particle (DemSlabs refreshes it and takes its forces back).
  static constexpr std::size_t remote_owner = static_cast<std::size_t>(-1);
  /// Appends a copy of another rank's particle (position already shifted to this rank's side of a periodic seam).
  std::size_t add_remote_ghost(const ParticleState& p, const GhostCoupling& coupling = {});
  /// The row whose coupling columns hold particle k's: its own for owned and remote ghosts, the owner's for images.
  [[nodiscard]] std::size_t coupling_row(std::size_t k) const {
    if (k < n_owned_) return k;
    const std::size_t o = ghost_owner_[k - n_owned_];
    return o == remote_owner ? k : o;
  }
  [[nodiscard]] std::size_t ghost_owner(std::size_t ghost) const { return ghost_owner_[ghost - n_owned_]; }
  [[nodiscard]] const hs::common::Vec3& ghost_shift_m(std::size_t ghost) const { return ghost_shift_[ghost - n_owned_]; }
  /// Copies position (+ shift), velocity and angular velocity from the owners (the forward halo exchange); remote
  /// ghosts are left to DemSlabs.
  void update_ghosts();
  /// Adds the forces and torques accumulated on ghosts to their owners (the reverse halo exchange); remote ghosts
  /// are left to DemSlabs, which folds them first (a remote ghost's owner may be a periodic image here).
  void fold_ghost_forces();

  /// Every column of owned particle i (coupling data, wall history, id and inlet opening included) appended to
  /// `out` as doubles: what a particle takes along when it moves to another rank.
  void pack_owned(std::size_t i, std::vector<double>& out);
  /// Appends an owned particle from pack_owned()'s doubles (removes all ghosts first); returns its index.
  std::size_t add_packed(const double* packed);
  /// How many doubles pack_owned() appends.
  [[nodiscard]] std::size_t packed_size();

 private:
  template <typename F>
  void for_each_column(F&& f);
  /// Applies f to every column, the integer ones (id, inlet opening) included.
  template <typename F>
  void for_each_any_column(F&& f);
  void resize(std::size_t n);

  std::size_t n_owned_ = 0;
  bool external_used_ = false;
  bool drag_used_ = false;
  Vec3Columns pos_, vel_, omega_, force_, torque_;
  Column radius_, mass_;
  std::vector<std::int64_t> id_;
  std::vector<std::int32_t> inlet_opening_;
  Vec3Columns ext_force_, ext_torque_, fluid_vel_, drag_impulse_, lift_, wall_shear_, fluid_omega_;
  Column drag_beta_, di_, rot_drag_;
  std::vector<std::size_t> ghost_owner_;
  std::vector<hs::common::Vec3> ghost_shift_;
};

}  // namespace hs::unresolved
