// SPDX-License-Identifier: MIT
// `hemoscale validate tumbling-threshold`: where the resolved cell stops tumbling and starts to tank-tread, vs
// Fischer & Korzeniewski 2013.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {
int validate_tumbling_threshold(const hs::common::TaskOptions& options);
}  // namespace hs::resolved
