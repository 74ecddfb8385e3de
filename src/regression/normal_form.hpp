// SPDX-License-Identifier: MIT
// An expression as a sorted sum of products of powers: the form in which the order of operands, the grouping of
// products and sums, division and square roots no longer show, for the recovery judge.
#pragma once

#include <cstddef>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

/// a * (b / c), b * a / c and a / (c / b) have one normal form, so do sqrt(p * q) and sqrt(q) * sqrt(p), and
/// x3*y3 + y1*x1 and x1*y1 + x3*y3. Powers are split over products and merged over equal bases as for positive
/// arguments ((p q)^e = p^e q^e, sqrt(x^2) = x): the recovery judge's use, whose Feynman variables are sampled from
/// positive ranges; not an identity for negative ones. Numbers only in products' coefficients and constant terms;
/// a numeric factor is multiplied into every term of a sum it multiplies.
struct NormalForm {
  enum class Kind { Constant, Variable, Sum, Product, Call };
  Kind kind = Kind::Constant;
  double value = 0.0;               // Constant: the number; Product: the coefficient
  std::size_t variable = 0;         // Variable: the feature index
  Op call = Op::Const;              // Call: the function (exp, log, sin, ..., pow with a non-constant exponent)
  std::vector<NormalForm> parts;    // Sum: the terms; Product: the bases; Call: the arguments
  std::vector<double> exponents;    // Product: each base's exponent
};

[[nodiscard]] NormalForm normal_form(const Expression& e);

/// The same structure, every number (constants, coefficients, exponents) within `tolerance` relative.
[[nodiscard]] bool same_normal_form(const NormalForm& a, const NormalForm& b, double tolerance);

/// SRBench's slack at the root: `additive` drops a sum's constant term; otherwise the root's overall factor is
/// divided out (a product's coefficient, or a sum's first term's coefficient from every term).
[[nodiscard]] NormalForm without_root_constant(const NormalForm& f, bool additive);

}  // namespace hs::regression
