// SPDX-License-Identifier: MIT
// `hemoscale validate stretching`: optical-tweezers stretching against Mills et al. 2004.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {
int validate_stretching(const hs::common::TaskOptions& options);
}  // namespace hs::resolved
