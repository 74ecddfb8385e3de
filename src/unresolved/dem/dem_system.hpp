// SPDX-License-Identifier: MIT
// One DEM block: particles, neighbour list, contacts, walls, periodic halo and the time step, as named stages.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "common/geometry/shape.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/drag_limited_step.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/neighbor_list.hpp"
#include "unresolved/dem/pair_contacts.hpp"
#include "unresolved/dem/particle_params.hpp"
#include "unresolved/dem/particle_store.hpp"
#include "unresolved/dem/wall_contacts.hpp"

namespace hs::unresolved {

struct DemSettings {
  ParticleParams params;
  Domain domain;
  double time_step_s;
};

/// Counters of the last step (diagnostics and benchmarks).
struct DemStepStats {
  std::size_t pair_contacts = 0;
  std::size_t wall_contacts = 0;
  std::size_t list_builds = 0;   // since construction
};

/// Advances the particles of one block by velocity Verlet (exact in the linear drag, see exponential_verlet.hpp):
///   half kick -> drift -> [rebuild: wrap, cell sort, periodic ghosts, neighbour list, wall candidates | ghost
///   update] -> forces: pairs, ghost fold, walls, hook -> half kick (which adds external_force_N()).
/// Owned particles are re-sorted at list rebuilds: hold on to id(), not to indices, across steps.
/// The coupling reads and writes per-particle data through particles() (external force, drag coefficient,
/// fluid velocity, drag impulse, DI); after adding or removing particles call particles_changed().
class DemSystem {
 public:
  /// Throws ConfigError when the time step violates 0.1 min(t_Rayleigh, t_Hertz) or a periodic length is below
  /// two neighbour cut-offs. `walls` (may be null) must outlive the system. `slabs` (may be null: the whole box
  /// here) distributes the particles over z-slabs (dem_slabs.hpp); it must outlive the system, and every rank then
  /// calls step(), initialize() and the other collective members together, each holding its slab's particles.
  DemSystem(const DemSettings& settings, const hs::common::Shape* walls, DemSlabs* slabs = nullptr);

  ParticleStore& particles() { return particles_; }
  [[nodiscard]] const ParticleStore& particles() const { return particles_; }
  [[nodiscard]] const ParticleParams& params() const { return settings_.params; }
  [[nodiscard]] const Domain& domain() const { return settings_.domain; }
  [[nodiscard]] double time_step_s() const { return settings_.time_step_s; }
  /// Changes the step between steps (the coupling's drag-limited sub-step); the caller answers for its stability
  /// (drag_limited_step()). The tangential springs carry over (they integrate v_t dt with the new dt).
  void set_time_step_s(double dt_s);
  /// The drag-limited step of the particles as they are now (drag_limited_step.hpp), after a fresh neighbour list
  /// (initializes if needed): the bound counts the listed pairs, and a list built from the current positions is
  /// the same in a run and in its restart, so both choose the same step.
  [[nodiscard]] DragLimitedStep drag_limited_step();
  [[nodiscard]] const NeighborList& neighbor_list() const { return list_; }
  /// The slabs this system runs on (null: the whole box here).
  [[nodiscard]] DemSlabs* slabs() const { return slabs_; }
  [[nodiscard]] const DemStepStats& stats() const { return stats_; }

  /// Adds an owned particle of the configured size and density (id = running count unless given).
  std::size_t add_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s = {},
                           std::optional<std::int64_t> id = std::nullopt);
  /// Between steps, unlike add_particle(): keeps the contact springs and the forces of the particles present, so
  /// the run goes on as if the new particle had always been there. pre: it touches no particle and no wall (its
  /// contact force is zero; a force hook acts on it from the next step on). Returns its index until the next step.
  std::size_t insert_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s, std::int64_t id);
  /// Between steps: removes the owned particles with remove[i] true (ParticleStore::remove_owned); the others
  /// keep their contact springs and forces (a force from a removed partner acts for the next half kick only).
  std::size_t remove_particles(const std::vector<bool>& remove);
  /// Call after changing particles() structurally (added/removed particles, moved positions by hand).
  void particles_changed() { initialized_ = false; }
  /// What insert_particle() and remove_particles() do first: takes the contact springs from the list, so the next
  /// step rebuilds with them and keeps the forces. On slabs every rank calls it when any rank edits (the rebuild that
  /// follows is collective).
  void begin_edit();
  /// Called in every force evaluation after contacts, before the second half kick: may add to force_N() and
  /// torque_Nm() of owned particles (e.g. forces that depend on the current positions).
  void set_force_hook(std::function<void(ParticleStore&)> hook) { hook_ = std::move(hook); }

  /// Checks particles against the walls (ConfigError for a centre outside the geometry), builds the lists and
  /// evaluates the forces. step() calls it when needed.
  void initialize();
  /// One DEM step of time_step_s().
  void step();
  /// Contact springs of the current list (for checkpoints), keyed by particle ids.
  /// Before the first step, or between an edit (or a restart) and the next step, the springs waiting to be restored.
  [[nodiscard]] ContactHistory contact_history() const {
    if (!initialized_) return restoring_ ? pending_history_ : ContactHistory{};
    return list_.extract_history(particles_);
  }
  /// Restart: the next initialize() uses these springs and keeps the forces now in particles() (read from a
  /// checkpoint) instead of evaluating them, so the run continues as if never stopped (up to round-off).
  void restore_contact_history(ContactHistory history);

  /// Re-evaluates the Hertz-time check with a measured relative speed (NumericalError if violated).
  void check_time_step_at(double max_relative_speed_m_s) const;
  /// Over every rank's particles (collective with slabs).
  [[nodiscard]] double max_speed_m_s() const;

 private:
  /// A sphere of the settings' radius and mass at rest in rotation.
  [[nodiscard]] ParticleState new_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s,
                                           std::int64_t id) const;
  void rebuild();
  void compute_forces();

  /// The box this block integrates: the settings' box, or this rank's slab of it.
  [[nodiscard]] const Domain& block_domain() const { return slabs_ != nullptr ? slabs_->block_domain() : settings_.domain; }

  DemSettings settings_;
  const hs::common::Shape* walls_;
  DemSlabs* slabs_;
  HertzContactLaw law_;
  ParticleStore particles_;
  NeighborList list_;
  PairContacts pairs_;
  std::unique_ptr<WallContacts> wall_contacts_;
  std::function<void(ParticleStore&)> hook_;
  DemStepStats stats_;
  double ghost_width_m_ = 0.0;
  bool initialized_ = false;
  bool restoring_ = false;
  ContactHistory pending_history_;
};

}  // namespace hs::unresolved
