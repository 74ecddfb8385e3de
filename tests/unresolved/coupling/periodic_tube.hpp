// SPDX-License-Identifier: MIT
// The set-up the coupling tests share: a tube of diameter D along z, periodic over its length, D / 10 cells across,
// filled with plasma driven at a fixed flow rate.
#pragma once

#include "common/geometry/tube.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"

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

/// Plasma on that grid with tight solver tolerances, driven along z at `flow_rate_m3_s` (0: no net flux).
inline FvmSolver tube_plasma(const FvmGrid& grid, double density_kg_m3, double kinematic_viscosity_m2_s, double dt_s,
                             double flow_rate_m3_s) {
  return FvmSolver(grid, {.density_kg_m3 = density_kg_m3, .kinematic_viscosity_m2_s = kinematic_viscosity_m2_s},
                   {.dt_s = dt_s, .pressure = {.tolerance = 1e-10, .rel_tol = 0.0}, .momentum_tolerance = 1e-12},
                   {.mode = FlowDrive::Mode::flow_rate, .axis = 2, .flow_rate_m3_s = flow_rate_m3_s});
}

}  // namespace hs::unresolved::test
