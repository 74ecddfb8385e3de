// SPDX-License-Identifier: MIT
// The symbolic-regression benchmark (Feynman recovery, evaluator speed).
#pragma once

#include "common/case_request.hpp"

namespace hs::bench {

/// Median evaluations (rows) per second of the compiled evaluator on a 20-node expression, one core.
[[nodiscard]] double evaluator_evaluations_per_second(int repetitions);
/// `hemoscale bench regression [--quick] [--json FILE]`.
int run_regression_bench(const hs::common::TaskOptions& options);

}  // namespace hs::bench
