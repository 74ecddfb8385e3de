// SPDX-License-Identifier: MIT
// Whether a formula's value is a small difference of large terms (a fit that a small change of data overturns).
#pragma once

#include "regression/data_view.hpp"
#include "regression/expression.hpp"

namespace hs::regression {

/// The root's additive terms (the operands of nested + and -, constants included), evaluated on every row:
/// the median over rows of sum|term| / |sum of terms|. 1: no cancellation; 10: the terms are ten times the
/// result, so about one significant digit of each is spent cancelling the others. A single term gives 1.
[[nodiscard]] double cancellation_ratio(const Expression& e, const DataView& x);

/// Above this ratio `hemoscale fit` warns that the chosen formula relies on a cancellation of large terms.
inline constexpr double cancellation_warning_ratio = 10.0;

}  // namespace hs::regression
