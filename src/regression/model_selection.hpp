// SPDX-License-Identifier: MIT
// A held-out test split, k-fold cross-validation of the Pareto front, and the choice of the final model.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "regression/symbolic_regressor.hpp"

namespace hs::regression {

struct Scores {
  double mae = 0.0, mse = 0.0, rmse = 0.0, r2 = 0.0;
};
[[nodiscard]] Scores score(std::span<const double> y, std::span<const double> p);

struct Split {
  std::vector<std::size_t> train, test;
};
/// A seeded shuffle; the last round(test_fraction * n) rows are the test set.
[[nodiscard]] Split train_test_split(std::size_t n, double test_fraction, std::uint64_t seed);
/// A seeded shuffle dealt into k folds; returns the held-out rows of each fold (indices into 0..n-1).
[[nodiscard]] std::vector<std::vector<std::size_t>> k_folds(std::size_t n, int k, std::uint64_t seed);

struct ValidatedModel {
  Expression expression;          // the chosen model (simplified, constants refitted on all training rows)
  Scores train, cv, test;         // cv: out-of-fold predictions over the training rows
  std::vector<ParetoEntry> front; // with cv_loss filled in
  SearchResult search;
  Split split;
};

struct ValidationSettings {
  double test_fraction = 0.2;     // held out, never seen by the search
  int folds = 5;                  // k-fold CV of every front member (<= 1: no CV, train loss decides)
  int refit_iterations = 20;      // LM steps when refitting a front member's constants on a fold
  bool select_from_front = true;  // false: gplearn's choice, the program of lowest raw training loss
};

/// Splits, searches on the training rows, cross-validates the front, picks the simplest front member with
/// cv loss <= selection_tolerance * the best cv loss, refits it on all training rows and scores it on the test set.
[[nodiscard]] ValidatedModel fit_validated(const SearchSettings& search, const ValidationSettings& validation,
                                           const std::vector<std::vector<double>>& columns,
                                           const std::vector<double>& y);

/// Refit of an expression's constants on (x, y) by Levenberg-Marquardt (no scaling); returns the refitted copy.
[[nodiscard]] Expression refit_constants(const Expression& e, const DataView& x, std::span<const double> y,
                                         int iterations);

}  // namespace hs::regression
