// SPDX-License-Identifier: MIT
// Pairs bootstrap of a formula's constants.
#include "regression/bootstrap_constants.hpp"

#include <random>

#include "regression/data_view.hpp"
#include "regression/model_selection.hpp"

namespace hs::regression {

std::vector<std::vector<double>> bootstrap_constants(const Expression& e, const std::vector<std::vector<double>>& x,
                                                     const std::vector<double>& y, int replicates, std::uint64_t seed,
                                                     int iterations) {
  const auto positions = e.constant_positions();
  if (positions.empty() || y.empty()) return {std::vector<double>{}};
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> row(0, y.size() - 1);
  std::vector<std::vector<double>> out;
  for (int b = 0; b < replicates; ++b) {
    std::vector<std::size_t> rows(y.size());
    for (auto& r : rows) r = row(rng);
    std::vector<double> yb(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) yb[i] = y[rows[i]];
    const ColumnData xb = ColumnData::pick(x, rows);
    const Expression refit = refit_constants(e, xb.view(), yb, iterations);
    std::vector<double> constants;
    for (std::size_t p : refit.constant_positions()) constants.push_back(refit[p].value);
    if (constants.size() == positions.size()) out.push_back(std::move(constants));
  }
  return out;
}

}  // namespace hs::regression
