// SPDX-License-Identifier: MIT
// The local shear rate of a velocity gradient, as the coupling's closures take it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "common/vec3.hpp"

namespace hs::unresolved {

/// sqrt(2 S:S) of a velocity gradient g[a][b] = du_a/dx_b, 1/s (S its symmetric part).
[[nodiscard]] inline double shear_rate(const std::array<common::Vec3, 3>& g) {
  double s2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double s = 0.5 * (g[static_cast<std::size_t>(a)][b] + g[static_cast<std::size_t>(b)][a]);
      s2 += s * s;
    }
  }
  return std::sqrt(2.0 * s2);
}

}  // namespace hs::unresolved
