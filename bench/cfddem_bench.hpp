// SPDX-License-Identifier: MIT
// `hemoscale bench cfddem`: coupled CFD-DEM wall time per CFD step and peak memory for 1e4, 1e5, 1e6 RBCs in a
// periodic tube and 1e4, 1e5 in an open tube with cells injected and removed.
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {

int run_cfddem_bench(const hs::common::TaskOptions& options);

}  // namespace hs::bench
