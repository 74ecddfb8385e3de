// SPDX-License-Identifier: MIT
// The cancellation ratio of a formula's top-level sum.
#include "regression/cancellation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "regression/compiled_program.hpp"

namespace hs::regression {
namespace {

/// Collects the additive terms under node i (sign folded into the term's evaluation later).
void collect_terms(const Expression& e, std::size_t i, double sign, std::vector<std::pair<Expression, double>>& out) {
  const Op op = e[i].op;
  if (op == Op::Add || op == Op::Sub) {
    const std::size_t b = e.subtree_end(i + 1);
    collect_terms(e, i + 1, sign, out);
    collect_terms(e, b, op == Op::Sub ? -sign : sign, out);
  } else if (op == Op::Neg) {
    collect_terms(e, i + 1, -sign, out);
  } else {
    out.emplace_back(e.subtree(i), sign);
  }
}

}  // namespace

double cancellation_ratio(const Expression& e, const DataView& x) {
  std::vector<std::pair<Expression, double>> terms;
  collect_terms(e, 0, 1.0, terms);
  if (terms.size() < 2 || x.rows == 0) return 1.0;
  std::vector<double> sum(x.rows, 0.0), magnitude(x.rows, 0.0), t(x.rows);
  for (const auto& [term, sign] : terms) {
    CompiledProgram(term).evaluate(x, t);
    for (std::size_t r = 0; r < x.rows; ++r) {
      sum[r] += sign * t[r];
      magnitude[r] += std::abs(t[r]);
    }
  }
  std::vector<double> ratio(x.rows);
  for (std::size_t r = 0; r < x.rows; ++r) {
    ratio[r] = std::abs(sum[r]) > 0.0 ? magnitude[r] / std::abs(sum[r]) : HUGE_VAL;
  }
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<long>(ratio.size() / 2), ratio.end());
  return ratio[ratio.size() / 2];
}

}  // namespace hs::regression
