// SPDX-License-Identifier: MIT
// `hemoscale validate capsule`: the neo-Hookean capsule's steady Taylor deformation in shear vs the published benchmarks.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {
int validate_capsule(const hs::common::TaskOptions& options);
}  // namespace hs::resolved
