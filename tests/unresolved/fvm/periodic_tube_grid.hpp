// SPDX-License-Identifier: MIT
// A tube of diameter D along z and its finite-volume grid, periodic over its length: shared by the FVM and the
// coupling tests.
#pragma once

#include <cmath>

#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_grid.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved::test {

/// The plasma (rbc_blood_properties.csv) and the 20 um tube, driven to 1 mm/s on the centreline, of the
/// variable-viscosity and pressure-coupling tests.
namespace plasma_tube {
inline constexpr double kRho = 1025.0;
inline constexpr double kNu = 1.2e-6;
inline constexpr double kRadius = 10e-6;
inline constexpr double kGradient = -5e4;   // Pa/m
}  // namespace plasma_tube

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

/// A viscous core: viscosity factor m in the cells whose centre lies within radius a of the z axis, 1 elsewhere.
inline void set_viscous_core(FvmSolver& solver, const FvmGrid& grid, double a, double m) {
  BlockField<double>& factor = solver.viscosity_factor();
  const auto& n = grid.cells();
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const auto x = grid.cell_centre_m(i, j, k);
        factor(i, j, k) = std::hypot(x[0], x[1]) < a ? m : 1.0;
      }
    }
  }
  solver.coupling_fields_changed();
}

}  // namespace hs::unresolved::test
