// SPDX-License-Identifier: MIT
// The stenosis case: one RBC released slightly off-centre flows through a periodic planar stenosed channel (seed
// paper section 3.2 after Hsieh 2020); D_x, D_y, D_z = L_i / 7.82 um are tracked through the constriction.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Runs a case of type "stenosis": plasma driven by a body force calibrated on the plasma alone to the case's flow
/// rate, one RBC released upstream of the throat at y0 = initial_height H; stops when the centroid passes stop_x_m
/// (exit code 0) or at max_time_s (exit code 1, not passed; --quick: 0). Writes timeseries.csv (t, centroid, D_x,
/// D_y, D_z, DI, wall gap, flow rate), summary.json (D upstream / at the throat / downstream, D_x peak and where,
/// Re, Ca at the throat, confinement), membrane.pvd/fields.pvd + vtk/, units.txt, log.txt; resumable (--resume).
int run_stenosis(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
