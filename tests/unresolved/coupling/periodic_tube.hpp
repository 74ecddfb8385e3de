// SPDX-License-Identifier: MIT
// The set-up the coupling tests share: the periodic tube of ../fvm/periodic_tube_grid.hpp filled with plasma driven
// at a fixed flow rate.
#pragma once

#include "../fvm/periodic_tube_grid.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"

namespace hs::unresolved::test {

/// Plasma on that grid with tight solver tolerances, driven along z at `flow_rate_m3_s` (0: no net flux).
inline FvmSolver tube_plasma(const FvmGrid& grid, double density_kg_m3, double kinematic_viscosity_m2_s, double dt_s,
                             double flow_rate_m3_s) {
  return FvmSolver(grid, {.density_kg_m3 = density_kg_m3, .kinematic_viscosity_m2_s = kinematic_viscosity_m2_s},
                   {.dt_s = dt_s, .pressure = {.tolerance = 1e-10, .rel_tol = 0.0}, .momentum_tolerance = 1e-12},
                   {.mode = FlowDrive::Mode::flow_rate, .axis = 2, .flow_rate_m3_s = flow_rate_m3_s});
}

}  // namespace hs::unresolved::test
