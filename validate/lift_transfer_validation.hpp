// SPDX-License-Identifier: MIT
// `hemoscale validate lift-transfer`: the learned lift closure against resolved runs in a tube it was not fitted in.
#pragma once

#include "common/case_request.hpp"

namespace hs::closures {
int validate_lift_transfer(const hs::common::TaskOptions& options);
}  // namespace hs::closures
