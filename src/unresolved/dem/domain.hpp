// SPDX-License-Identifier: MIT
// The box a DEM block covers and which of its directions are periodic.
#pragma once

#include <array>

#include "common/geometry/shape.hpp"

namespace hs::unresolved {

/// Axis-aligned box in metres. Along a periodic axis a particle leaving through one face re-enters through
/// the other; along a non-periodic axis the box only bounds the cell grid (walls come from a Shape).
struct Domain {
  hs::common::Box3 box;
  std::array<bool, 3> periodic{false, false, false};

  [[nodiscard]] double length_m(int axis) const { return box.hi[axis] - box.lo[axis]; }
};

}  // namespace hs::unresolved
