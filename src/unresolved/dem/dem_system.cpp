// SPDX-License-Identifier: MIT
// The DEM time step of one block.
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/dem/exponential_verlet.hpp"
#include "unresolved/dem/periodic_halo.hpp"

namespace hs::unresolved {
namespace {

void check_periodic_lengths(const Domain& domain, double cutoff_m) {
  for (int a = 0; a < 3; ++a) {
    if (domain.periodic[a] && domain.length_m(a) < 2.0 * cutoff_m) {
      throw hs::common::ConfigError(fmt::format(
          "DEM: periodic length {:.4g} m along axis {} is below two neighbour cut-offs (2 x (d_max + skin) = {:.4g} m); "
          "make the periodic domain longer", domain.length_m(a), "xyz"[a], 2.0 * cutoff_m));
    }
  }
}

}  // namespace

DemSystem::DemSystem(const DemSettings& settings, const hs::common::Shape* walls, DemSlabs* slabs)
    : settings_(settings), walls_(walls), slabs_(slabs), law_(settings.params), list_(settings.params.skin_m), pairs_(law_) {
  check_time_step(settings_.params, settings_.time_step_s);
  check_periodic_lengths(block_domain(), settings_.params.diameter_m + settings_.params.skin_m);
  if (slabs_ != nullptr) slabs_->check_thickness(settings_.params.diameter_m + settings_.params.skin_m);
  if (walls_ != nullptr) wall_contacts_ = std::make_unique<WallContacts>(*walls_, law_);
}

ParticleState DemSystem::new_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s,
                                      std::int64_t id) const {
  const ParticleParams& p = settings_.params;
  return {.position_m = position_m,
          .velocity_m_s = velocity_m_s,
          .angular_velocity_rad_s = {},
          .radius_m = p.radius_m(),
          .mass_kg = p.mass_kg(),
          .id = id};
}

std::size_t DemSystem::add_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s,
                                    std::optional<std::int64_t> id) {
  initialized_ = false;
  return particles_.add(new_particle(position_m, velocity_m_s, id.value_or(static_cast<std::int64_t>(particles_.n_owned()))));
}

void DemSystem::begin_edit() {
  // The list indexes the particles as they are now: take the springs before the first edit changes them. Later
  // edits before the next step, or edits after particles_changed(), have no valid list to take them from.
  if (initialized_) {
    pending_history_ = list_.extract_history(particles_);
    restoring_ = true;   // initialize() keeps the forces in particles() instead of evaluating them again
  }
  initialized_ = false;
}

std::size_t DemSystem::insert_particle(const hs::common::Vec3& position_m, const hs::common::Vec3& velocity_m_s,
                                       std::int64_t id) {
  begin_edit();
  return particles_.add(new_particle(position_m, velocity_m_s, id));
}

std::size_t DemSystem::remove_particles(const std::vector<bool>& remove) {
  begin_edit();
  return particles_.remove_owned(remove);
}

void DemSystem::initialize() {
  if (walls_ != nullptr) {
    std::string outside;
    const auto& pos = particles_.position_m();
    for (std::size_t i = 0; i < particles_.n_owned() && outside.empty(); ++i) {
      const hs::common::Vec3 x{pos[0][i], pos[1][i], pos[2][i]};
      if (walls_->signed_distance(x) > 0.0) {
        outside = fmt::format(
            "DEM: particle {} at ({:.4g}, {:.4g}, {:.4g}) m has its centre outside the geometry (signed distance "
            "{:.3g} m > 0); particles must start inside the fluid region", particles_.id()[i], x.x, x.y, x.z,
            walls_->signed_distance(x));
      }
    }
    // Every rank throws or none does (a rank left behind would wait in the next exchange).
    const bool any = slabs_ != nullptr ? slabs_->any(!outside.empty()) : !outside.empty();
    if (any) {
      throw hs::common::ConfigError(outside.empty() ? "DEM: a particle of another rank has its centre outside the geometry"
                                                    : outside);
    }
  }
  particles_.clear_ghosts();
  // A fresh list forgets the springs, except on a restart or after an edit (they are in pending_history_). The
  // same list object keeps its build count growing, which PairContacts uses to know its plan is stale.
  if (!restoring_) list_ = NeighborList(settings_.params.skin_m);
  rebuild();
  if (!restoring_) compute_forces();   // a restart keeps the checkpointed forces (their springs are already updated)
  restoring_ = false;
  initialized_ = true;
}

void DemSystem::restore_contact_history(ContactHistory history) {
  pending_history_ = std::move(history);
  restoring_ = true;
  initialized_ = false;
}

void DemSystem::rebuild() {
  ContactHistory history = restoring_ ? std::move(pending_history_) : list_.extract_history(particles_);
  pending_history_ = {};
  particles_.clear_ghosts();
  // Particles that left the slab go to their new owner, with the springs of the pairs they compute.
  if (slabs_ != nullptr) history = slabs_->migrate(particles_, history);
  double r_max = 0.0;
  for (std::size_t i = 0; i < particles_.n_owned(); ++i) r_max = std::max(r_max, particles_.radius_m()[i]);
  if (slabs_ != nullptr) r_max = slabs_->max(r_max);   // one cut-off everywhere: both sides see the same pairs
  const double cutoff = 2.0 * r_max + settings_.params.skin_m;
  const Domain& domain = block_domain();
  check_periodic_lengths(domain, cutoff);
  if (slabs_ != nullptr) slabs_->check_thickness(cutoff);
  ghost_width_m_ = cutoff;
  wrap_periodic(particles_, domain);
  particles_.permute_owned(cell_sort_order(particles_, domain, cutoff));
  build_periodic_ghosts(particles_, domain, ghost_width_m_);
  if (slabs_ != nullptr) slabs_->exchange_ghosts(particles_, ghost_width_m_);
  const hs::common::Vec3 pad{cutoff, cutoff, cutoff};
  list_.build(particles_, domain.box.lo - pad, domain.box.hi + pad, history);
  if (wall_contacts_) wall_contacts_->select_candidates(particles_, settings_.params.skin_m);
  stats_.list_builds = list_.n_builds();
}

void DemSystem::compute_forces() {
  const double dt = settings_.time_step_s;
  stats_.pair_contacts = pairs_.compute(particles_, list_, dt);
  if (slabs_ != nullptr) slabs_->fold_ghost_forces(particles_);
  particles_.fold_ghost_forces();
  stats_.wall_contacts = wall_contacts_ ? wall_contacts_->compute(particles_, dt) : 0;
  if (hook_) hook_(particles_);
}

void DemSystem::step() {
  if (!initialized_) initialize();
  const double dt = settings_.time_step_s;
  exponential_half_kick(particles_, 0.5 * dt);
  drift(particles_, dt);
  const bool needs_rebuild = list_.needs_rebuild(particles_);
  if (slabs_ != nullptr ? slabs_->any(needs_rebuild) : needs_rebuild) {
    rebuild();
  } else {
    particles_.update_ghosts();
    if (slabs_ != nullptr) slabs_->update_ghosts(particles_);
  }
  compute_forces();
  exponential_half_kick(particles_, 0.5 * dt);
}

void DemSystem::set_time_step_s(double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) {
    throw hs::common::NumericalError(fmt::format("DEM: time step {:.4g} s must be finite and > 0", dt_s));
  }
  settings_.time_step_s = dt_s;
}

DragLimitedStep DemSystem::drag_limited_step() {
  if (initialized_) {
    rebuild();   // keeps the forces (they move with their particles) and the springs (by id)
  } else {
    initialize();
  }
  return hs::unresolved::drag_limited_step(particles_, list_, law_, wall_contacts_.get(), slabs_);
}

double DemSystem::max_speed_m_s() const {
  const auto& v = particles_.velocity_m_s();
  double v2 = 0.0;
  for (std::size_t i = 0; i < particles_.n_owned(); ++i) {
    v2 = std::max(v2, v[0][i] * v[0][i] + v[1][i] * v[1][i] + v[2][i] * v[2][i]);
  }
  return std::sqrt(slabs_ != nullptr ? slabs_->max(v2) : v2);
}

void DemSystem::check_time_step_at(double max_relative_speed_m_s) const {
  ParticleParams p = settings_.params;
  p.max_impact_velocity_m_s = std::max(max_relative_speed_m_s, 1e-300);
  try {
    check_time_step(p, settings_.time_step_s);
  } catch (const hs::common::ConfigError& e) {
    throw hs::common::NumericalError(fmt::format("DEM time-step criterion violated during the run: {}", e.what()));
  }
}

}  // namespace hs::unresolved
