// SPDX-License-Identifier: MIT
// The tube-poiseuille case: plasma in a periodic tube driven by a body force, checked against Poiseuille.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {

/// Runs cases of type "tube-poiseuille" to steady state and writes units.txt, case.resolved.toml, summary.json,
/// timeseries.csv, vtk/ + fields.pvd and log.txt into a new run folder. Returns 0 when the centre-line speed and
/// the flow rate agree with Poiseuille within the case's acceptance, 1 otherwise. Bad input throws ConfigError.
int run_tube_poiseuille(const hs::common::CaseRequest& request);

}  // namespace hs::resolved
