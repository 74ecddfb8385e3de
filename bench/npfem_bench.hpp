// SPDX-License-Identifier: MIT
// `hemoscale bench npfem`: cost of one npFEM membrane step at 258 and 642 vertices.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {
int bench_npfem(const hs::common::TaskOptions& options);
}  // namespace hs::resolved
