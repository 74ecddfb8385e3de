// SPDX-License-Identifier: MIT
// `hemoscale bench dem`: DEM ns per particle-step on the LIGGGHTS rbcpack system, side by side with LIGGGHTS.
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {

int run_dem_bench(const hs::common::TaskOptions& options);

}  // namespace hs::bench
