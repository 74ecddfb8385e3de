// SPDX-License-Identifier: MIT
// Case type "stretching": optical-tweezers stretching of one RBC membrane (Mills et al. 2004), no fluid.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Reads [membrane] and [stretching], loads the cell force level by force level to steady state, writes
/// stretching.csv (diameters vs force with the Mills band), stretching.png, vtk/membrane_*.vtp + membrane.pvd,
/// summary.json and log.txt. Returns 0 when every level reached steady state inside the band, 1 otherwise.
int run_stretching(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
