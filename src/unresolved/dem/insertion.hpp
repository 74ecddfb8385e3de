// SPDX-License-Identifier: MIT
// Placing non-overlapping spheres inside a Shape at a target volume fraction (hematocrit).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry/shape.hpp"
#include "unresolved/dem/domain.hpp"

namespace hs::unresolved {

struct InsertionSpec {
  double volume_fraction;     // sphere volume / region volume, e.g. the tube hematocrit Ht_c
  double radius_m;
  std::uint64_t seed;
  std::string key = "hematocrit";   // the case key named in error messages
};

struct InsertionResult {
  std::vector<hs::common::Vec3> positions_m;
  double region_volume_m3 = 0.0;   // the shape inside the domain box
  double achieved_fraction = 0.0;
  bool used_lattice = false;       // random sequential addition did not finish: lattice fallback
};

/// Volume of the shape inside the domain box: exact for a Tube inside the box, otherwise a midpoint-rule count
/// on a grid of about 2e6 points (relative error ~ 1e-3 for smooth shapes).
[[nodiscard]] double region_volume_m3(const hs::common::Shape& shape, const Domain& domain);

/// N = round(fraction V / V_sphere) spheres with centres where signed_distance <= -r (whole sphere in the fluid),
/// inside the box (at least r from non-periodic faces), no two overlapping (minimum image along periodic axes).
/// Random sequential addition with the seed; if it stalls, N sites drawn at random from an FCC lattice of
/// spacing d (stretched to fit periodic lengths). Throws ConfigError naming the value and the achievable
/// maximum (the lattice capacity) when N spheres cannot fit.
[[nodiscard]] InsertionResult insert_at_volume_fraction(const hs::common::Shape& shape, const Domain& domain,
                                                        const InsertionSpec& spec);

}  // namespace hs::unresolved
