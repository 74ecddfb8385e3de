// SPDX-License-Identifier: MIT
// `hemoscale bench resolved`: cost of the coupled tube-drag case at the campaign resolution, and the campaign it implies.
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {
int run_resolved_bench(const hs::common::TaskOptions& options);
}  // namespace hs::bench
