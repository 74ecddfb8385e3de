// SPDX-License-Identifier: MIT
// The plate cases: one RBC in simple shear between moving walls (`shear`) and one RBC migrating in plane
// Poiseuille flow (`migration`, Shi et al. 2014 as restated in the seed paper section 3.1).
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Runs a case of type "shear": walls at y = 0 and H moving at -U/2 and +U/2 along x (U = gamma_dot H), periodic in
/// x and z, the fluid started on the Couette profile, one RBC released at the centre. Writes timeseries.csv (DI,
/// inclination, marker phase, centroid), summary.json (flow mode, tumbling period vs Jeffery, mean inclination,
/// tank-treading frequency, Re, Ca, gamma_dot), membrane.pvd/fields.pvd + vtk/, units.txt, log.txt. Returns 0.
int run_shear(const hs::common::CaseRequest& request);

/// Runs a case of type "migration": plane Poiseuille flow between resting walls at y = 0 and H (body force
/// g = 8 nu U_max / H^2, switched on smoothly), one RBC released at y0 = initial_height H. Writes the lateral
/// position vs time (timeseries.csv), summary.json (migration speed, lateral position at quarters of the run, Re =
/// rho H U_max / mu, Ca), frames. Returns 0.
int run_migration(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
