// SPDX-License-Identifier: MIT
// Case type "tube-plasma": plasma alone in a periodic straight tube, checked against Hagen-Poiseuille.
#pragma once

#include "common/case_request.hpp"

namespace hs::unresolved {

/// Runs cases/unresolved/tube-plasma-like folders; returns 0 when the flow rate is within
/// [check] max_error_pct of Poiseuille, 1 otherwise.
int run_tube_plasma(const hs::common::CaseRequest& request);

}  // namespace hs::unresolved
