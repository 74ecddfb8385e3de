// SPDX-License-Identifier: MIT
// Expansion of polynomial subexpressions into a canonical sum of monomials, so that equal polynomials
// written differently ((x + a)(x + b)*2.5 + c versus 2.5 x^2 + x) print the same.
#pragma once

#include "regression/expression.hpp"

namespace hs::regression {

/// Every maximal subtree built from +, -, *, neg, constants, variables and pow(., even integer <= 4) is
/// expanded into a sum of monomials (terms in a fixed order, coefficients below 1e-12 of the largest dropped)
/// when that is not longer than the subtree. Other subtrees are kept as they are.
[[nodiscard]] Expression expand_polynomials(const Expression& e);

}  // namespace hs::regression
