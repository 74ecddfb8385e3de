// SPDX-License-Identifier: MIT
// Algebraic simplification of expressions that keeps the protected semantics (constant folding, identities).
#pragma once

#include "regression/expression.hpp"

namespace hs::regression {

enum class SimplifyMode {
  Exact,       // only identities of the protected functions, for every finite input
  Algebraic,   // also rules of true division, (c1 * a) / (c2 * b) -> (c1/c2) * (a / b), and
               // sqrt(c * a) -> sqrt(|c|) * sqrt(a), sqrt(a * a) -> |a|, exp(log a) -> |a|, log(exp a) -> a: exact wherever no denominator is within 0.001 of zero
               // (and no exp/log argument leaves its protected range; callers re-score the result on their data)
};

/// Bottom-up rewriting until nothing changes: folds constant subtrees (with protected semantics), removes
/// neutral elements (x + 0, x * 1, x / 1, x^0), collapses x - x, x / x, -(-x), moves constants to the left
/// of + and *, merges chains of constants (c1 * (c2 * x) -> c * x), turns x / c into (1/c) * x and
/// x - c into -c + x.
[[nodiscard]] Expression simplify(const Expression& e, SimplifyMode mode = SimplifyMode::Exact);

/// Constants within a relative `tolerance` of a short decimal or binary fraction (integers, halves,
/// quarters, ..., hundredths) are replaced by it, e.g. 2.4999999999997 -> 2.5.
[[nodiscard]] Expression snap_constants(const Expression& e, double tolerance = 1e-9);

}  // namespace hs::regression
