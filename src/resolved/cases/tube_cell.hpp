// SPDX-License-Identifier: MIT
// The tube-cell case: one RBC in the periodic campaign tube, drag (centre fixed) or lift (axial motion only).
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Runs a case of type "tube-cell" until the drag, lift and DI signals have settled over [run] settle_periods whole
/// periods, or [run] max_time_s. Writes timeseries.csv, summary.json (results: period averages of DI, Cd, Cl with
/// spreads, flow mode, all dimensionless groups), membrane.pvd/fields.pvd + vtk/, units.txt, log.txt.
/// Returns 0 when it ran (1 if it stopped at the cap without settling). Bad input throws ConfigError.
int run_tube_cell(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
