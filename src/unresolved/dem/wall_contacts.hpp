// SPDX-License-Identifier: MIT
// Particle-wall contacts against a Shape's signed distance (the wall is the region where it is > 0).
#pragma once

#include <cstddef>
#include <vector>

#include "common/geometry/shape.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// A sphere of radius r at x overlaps the wall by delta = r + phi(x), phi the signed distance (< 0 in the
/// fluid); the normal is -grad phi (central differences). The wall is at rest, infinitely heavy and stiff
/// with the wall material: R* = r, m* = m (LIGGGHTS fix wall/gran, unresolved-methods.md 4.7). One contact
/// per particle (the nearest wall point), with its tangential history in ParticleStore::wall_shear_m().
class WallContacts {
 public:
  WallContacts(const hs::common::Shape& shape, const HertzContactLaw& law) : shape_(shape), law_(law) {}

  /// Keeps the owned particles that may touch the wall before the next list rebuild (phi > -(r + skin)).
  void select_candidates(const ParticleStore& particles, double skin_m);
  /// Adds the wall forces and torques to the owned particles; returns the number of wall contacts.
  std::size_t compute(ParticleStore& particles, double dt_s) const;
  /// The particles kept by the last select_candidates().
  [[nodiscard]] const std::vector<std::size_t>& candidates() const { return candidates_; }
  /// Overlap r + phi(x) of a sphere of radius r at x (> 0 in contact) and the wall's outward normal there.
  [[nodiscard]] double overlap_m(const hs::common::Vec3& x_m, double r_m) const { return r_m + shape_.signed_distance(x_m); }
  [[nodiscard]] hs::common::Vec3 outward_normal_at(const hs::common::Vec3& x_m, double r_m) const;

 private:
  [[nodiscard]] hs::common::Vec3 outward_normal(const hs::common::Vec3& x_m, double h_m) const;

  const hs::common::Shape& shape_;
  HertzContactLaw law_;
  std::vector<std::size_t> candidates_;
};

}  // namespace hs::unresolved
