// SPDX-License-Identifier: MIT
// The uncertainty of a chosen formula's constants: refitted on bootstrap resamples of the training rows.
#pragma once

#include <cstdint>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

/// `replicates` sets of the constants of `e` (in prefix order, Expression::constant_positions), each refitted by
/// Levenberg-Marquardt from the chosen values on n rows drawn with replacement from (x, y) (seeded). The spread of
/// the predictions over the sets is the formula's parameter uncertainty (Efron & Tibshirani 1993, the bootstrap of
/// a regression's residual-free "pairs" kind). A formula without constants gives one empty set.
[[nodiscard]] std::vector<std::vector<double>> bootstrap_constants(const Expression& e,
                                                                   const std::vector<std::vector<double>>& x,
                                                                   const std::vector<double>& y, int replicates,
                                                                   std::uint64_t seed, int iterations);

}  // namespace hs::regression
