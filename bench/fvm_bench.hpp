// SPDX-License-Identifier: MIT
// `hemoscale bench fvm`: the FVM fluid on the 3D lid-driven cube, side by side with OpenFOAM icoFoam.
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {

int run_fvm_bench(const hs::common::TaskOptions& options);

}  // namespace hs::bench
