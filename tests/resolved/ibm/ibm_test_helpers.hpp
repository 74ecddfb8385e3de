// SPDX-License-Identifier: MIT
// Shared by the immersed-boundary tests: markers on a sphere.
#pragma once

#include <cmath>
#include <numbers>

#include "resolved/ibm/immersed_boundary.hpp"

namespace hs::resolved {

/// Markers spread roughly every 1 lu over a sphere (Fibonacci lattice), at rest, each carrying its share of the area.
inline Markers sphere_markers(const common::Vec3& centre, double radius, int count) {
  Markers m;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    m.x_lu.push_back(centre + radius * common::Vec3{r * std::cos(golden * k), r * std::sin(golden * k), z});
    m.u_lu.push_back({});
    m.area_lu.push_back(4.0 * std::numbers::pi * radius * radius / count);
  }
  return m;
}

}  // namespace hs::resolved
