// SPDX-License-Identifier: MIT
// `hemoscale validate resolved-dataset`: the committed campaign dataset against its acceptance rules.
#pragma once

#include "common/case_request.hpp"

namespace hs::campaign {
int validate_resolved_dataset(const hs::common::TaskOptions& options);
}  // namespace hs::campaign
