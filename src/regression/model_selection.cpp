// SPDX-License-Identifier: MIT
// Train/test split, k-fold cross-validation of the Pareto front and final model choice.
#include "regression/model_selection.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

#include "regression/compiled_program.hpp"
#include "regression/simplify.hpp"

namespace hs::regression {
namespace {

std::vector<std::size_t> shuffled(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> index(n);
  std::iota(index.begin(), index.end(), std::size_t{0});
  std::mt19937_64 rng(seed ^ 0x5EEDF01DULL);
  for (std::size_t i = n; i > 1; --i) {   // Fisher-Yates with our own draws: identical on every platform
    const std::size_t j = static_cast<std::size_t>(rng() % i);
    std::swap(index[i - 1], index[j]);
  }
  return index;
}

std::vector<double> pick(const std::vector<double>& v, const std::vector<std::size_t>& index) {
  std::vector<double> out;
  out.reserve(index.size());
  for (std::size_t i : index) out.push_back(v[i]);
  return out;
}

std::vector<double> predict(const Expression& e, const DataView& x) {
  std::vector<double> p(x.rows);
  CompiledProgram(e).evaluate(x, p);
  return p;
}

// Out-of-fold predictions of `e` over the training rows: constants refitted on the other folds.
std::vector<double> out_of_fold(const Expression& e, const std::vector<std::vector<double>>& columns,
                                const std::vector<double>& y, const std::vector<std::vector<std::size_t>>& folds,
                                int iterations) {
  std::vector<double> oof(y.size());
  for (std::size_t f = 0; f < folds.size(); ++f) {
    std::vector<std::size_t> fit_rows;
    for (std::size_t g = 0; g < folds.size(); ++g) {
      if (g != f) fit_rows.insert(fit_rows.end(), folds[g].begin(), folds[g].end());
    }
    const ColumnData fit_x = ColumnData::pick(columns, fit_rows);
    const Expression refit = refit_constants(e, fit_x.view(), pick(y, fit_rows), iterations);
    const ColumnData held_x = ColumnData::pick(columns, folds[f]);
    const std::vector<double> p = predict(refit, held_x.view());
    for (std::size_t i = 0; i < folds[f].size(); ++i) oof[folds[f][i]] = p[i];
  }
  return oof;
}

// Constants set to zero and abs() removed one at a time (then simplified and refitted) while the training loss
// stays within round-off of where it was: removes terms such as 1e-16*T that LM leaves behind on exact data.
Expression prune_constants(Expression e, const DataView& x, std::span<const double> y, Metric metric, int iterations) {
  double mean = 0.0;
  for (double v : y) mean += v / static_cast<double>(y.size());
  const double null_loss = loss(metric, y, std::vector<double>(y.size(), mean));
  double base = loss(metric, y, predict(e, x));
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 0; k < e.size(); ++k) {
      if (e[k].op != Op::Const && e[k].op != Op::Abs) continue;
      // A constant set to 0, or an abs() removed (its argument keeps one sign on the data).
      Expression candidate = e;
      if (e[k].op == Op::Const) {
        candidate.nodes()[k].value = 0.0;
      } else {
        candidate.nodes().erase(candidate.nodes().begin() + static_cast<std::ptrdiff_t>(k));
      }
      candidate = simplify(candidate, SimplifyMode::Algebraic);
      if (candidate.size() >= e.size() || !candidate.well_formed()) continue;
      candidate = refit_constants(candidate, x, y, iterations);
      const double l = loss(metric, y, predict(candidate, x));
      if (l <= base * (1.0 + 1e-6) + 1e-12 * null_loss) {
        e = std::move(candidate);
        base = std::min(base, l);
        changed = true;
        break;
      }
    }
  }
  return e;
}

}  // namespace

Scores score(std::span<const double> y, std::span<const double> p) {
  return {.mae = mean_absolute_error(y, p), .mse = mean_squared_error(y, p), .rmse = root_mean_squared_error(y, p),
          .r2 = r_squared(y, p)};
}

Split train_test_split(std::size_t n, double test_fraction, std::uint64_t seed) {
  const auto index = shuffled(n, seed);
  const auto n_test = static_cast<std::size_t>(std::llround(test_fraction * static_cast<double>(n)));
  Split s;
  s.train.assign(index.begin(), index.end() - static_cast<std::ptrdiff_t>(n_test));
  s.test.assign(index.end() - static_cast<std::ptrdiff_t>(n_test), index.end());
  return s;
}

std::vector<std::vector<std::size_t>> k_folds(std::size_t n, int k, std::uint64_t seed) {
  const auto index = shuffled(n, seed + 1);
  std::vector<std::vector<std::size_t>> folds(static_cast<std::size_t>(std::max(k, 1)));
  for (std::size_t i = 0; i < n; ++i) folds[i % folds.size()].push_back(index[i]);
  return folds;
}

Expression refit_constants(const Expression& e, const DataView& x, std::span<const double> y, int iterations) {
  ScaledModel m{.tree = e, .offset = 0.0, .scale = 1.0};
  optimize_constants(m, x, y, iterations, false);
  return m.tree;
}

ValidatedModel fit_validated(const SearchSettings& search, const ValidationSettings& validation,
                             const std::vector<std::vector<double>>& columns, const std::vector<double>& y) {
  ValidatedModel out;
  out.split = train_test_split(y.size(), validation.test_fraction, search.seed);
  const ColumnData train_x = ColumnData::pick(columns, out.split.train);
  const ColumnData test_x = ColumnData::pick(columns, out.split.test);
  const std::vector<double> y_train = pick(y, out.split.train);
  const std::vector<double> y_test = pick(y, out.split.test);
  out.search = SymbolicRegressor(search).fit(train_x.view(), y_train);
  out.front = out.search.front;
  const bool cv = validation.folds > 1 && y_train.size() >= static_cast<std::size_t>(2 * validation.folds);
  const auto folds = k_folds(y_train.size(), validation.folds, search.seed);
  double best_cv = HUGE_VAL;
  for (auto& entry : out.front) {
    const auto p = cv ? out_of_fold(entry.expression, train_x.columns(), y_train, folds, validation.refit_iterations)
                      : predict(entry.expression, train_x.view());
    entry.cv_loss = loss(search.metric, y_train, p);
    best_cv = std::min(best_cv, entry.cv_loss);
  }
  const ParetoEntry* chosen = nullptr;
  for (const auto& entry : out.front) {
    if (entry.cv_loss <= search.selection_tolerance * best_cv) {
      chosen = &entry;
      break;
    }
  }
  out.expression = chosen && validation.select_from_front ? chosen->expression : out.search.best;
  if (out.expression.empty()) {   // only with dimensional constraints: every program was inconsistent
    throw std::runtime_error("no dimensionally consistent formula was found: check the units given to the fit, or "
                             "allow more generations");
  }
  if (search.lm_iterations > 0) {
    const Expression refit = refit_constants(out.expression, train_x.view(), y_train, validation.refit_iterations);
    const Expression pruned = prune_constants(refit, train_x.view(), y_train, search.metric, validation.refit_iterations);
    out.expression = simplify(snap_constants(pruned), SimplifyMode::Algebraic);
  }
  const auto p_train = predict(out.expression, train_x.view());
  out.train = score(y_train, p_train);
  out.cv = cv && chosen ? score(y_train, out_of_fold(out.expression, train_x.columns(), y_train, folds,
                                                     validation.refit_iterations))
                        : out.train;
  if (!y_test.empty()) out.test = score(y_test, predict(out.expression, test_x.view()));
  return out;
}

}  // namespace hs::regression
