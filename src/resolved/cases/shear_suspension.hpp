// SPDX-License-Identifier: MIT
// The `shear-suspension` case: many cells at a hematocrit in simple shear between moving plates (issue #24).
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Runs a case of type "shear-suspension": walls at y = 0 and H moving at -U/2 and +U/2 along x (U = gamma_dot H),
/// periodic in x and z, the fluid started on the Couette profile; N = round(phi V_box / V_cell) cells placed at random
/// without overlap (cell_placement), each with its own npFEM solve, the cell-cell contact repulsion between them and a
/// plate repulsion of the same form (CellSuspension). Writes timeseries.csv (summed stresslet, eta_r, closest
/// approach), summary.json (eta_r = 1 + <sum S_xy> / (V_box mu gamma_dot) over the second half with its batch-means
/// standard error, phi, Ca, Re), membranes.pvd + vtk/, units.txt, log.txt. Every rank holds every membrane (as
/// CoupledCell): np = 2 gives np = 1's series to round-off (tested). Bad input or a hematocrit the box cannot hold:
/// exit 2. Returns 0 (the run measures only).
int run_shear_suspension(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
