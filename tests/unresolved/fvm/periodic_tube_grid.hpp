// SPDX-License-Identifier: MIT
// A tube of diameter D along z and its finite-volume grid, periodic over its length: shared by the FVM and the
// coupling tests.
#pragma once

#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved::test {

inline hs::common::Tube tube_along_z(double diameter_m, double length_m) {
  return hs::common::Tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length_m}, .radius_m = 0.5 * diameter_m});
}

/// The grid of `tube` (which it keeps a reference to): box [-R, R]^2 x [0, L], periodic along z.
inline FvmGrid periodic_tube_grid(const hs::common::Tube& tube, double diameter_m, double length_m, int cells_across = 10) {
  const double r = 0.5 * diameter_m;
  FvmGridSpec spec{.box_m = {{-r, -r, 0.0}, {r, r, length_m}}, .dx_m = diameter_m / cells_across, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  return FvmGrid(tube, spec);
}

}  // namespace hs::unresolved::test
