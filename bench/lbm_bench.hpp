// SPDX-License-Identifier: MIT
// `hemoscale bench lbm`: lattice Boltzmann kernel speed against the machine's memory-bandwidth roofline.
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {

/// Measures the STREAM-like triad bandwidth, the roofline MLUPS of the fluid kernel and its measured MLUPS for a
/// periodic 128^3 box and the 50 um plasma tube at 1 and 2 threads; prints a table, writes JSON with --json.
int run_lbm_bench(const hs::common::TaskOptions& options);

}  // namespace hs::bench
