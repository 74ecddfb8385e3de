// SPDX-License-Identifier: MIT
// Genetic-programming symbolic regression (gplearn's algorithm, plus linear scaling, Levenberg-Marquardt
// constants and a Pareto archive), reproducible for a seed whatever the thread count.
#pragma once

#include <span>
#include <vector>

#include "regression/constant_optimizer.hpp"
#include "regression/data_view.hpp"
#include "regression/genetic_operators.hpp"
#include "regression/lexicase_selector.hpp"
#include "regression/pareto_front.hpp"
#include "regression/search_settings.hpp"

namespace hs::regression {

struct SearchResult {
  Expression best;                    // simplified expression of the lowest raw training loss (gplearn's choice)
  double best_loss = 0.0;             // its training loss
  std::vector<ParetoEntry> front;     // complexity vs training loss, simplified expressions
  int generations_run = 0;
  long evaluations = 0;               // model evaluations over the training rows, LM included
};

class SymbolicRegressor {
 public:
  explicit SymbolicRegressor(SearchSettings settings);

  /// Evolves a population on (x, y). Each offspring draws from its own generator seeded by
  /// (seed, generation, index), so the result is the same for any thread count.
  [[nodiscard]] SearchResult fit(const DataView& x, std::span<const double> y) const;

  /// offset + scale * tree, simplified, with offset/scale dropped when negligible and constants snapped.
  [[nodiscard]] static Expression materialize(const ScaledModel& model, double y_scale);

  [[nodiscard]] const SearchSettings& settings() const { return settings_; }

 private:
  struct Individual {
    ScaledModel model;
    double loss = 0.0;
    long evaluations = 0;
    std::vector<double> case_errors;   // |residual| on the lexicase cases (empty without lexicase)
    bool consistent = true;            // dimensionally (always, without feature_dimensions)
  };
  [[nodiscard]] Individual offspring(const std::vector<Individual>& pop, const std::vector<double>& penalised,
                                     const GeneticOperators& ops, const LexicaseSelector* lexicase,
                                     Rng& rng) const;
  void record(const std::vector<Individual>& pop, const DataView& x, std::span<const double> y, double y_scale,
              ParetoFront& archive, SearchResult& result) const;
  void evaluate(Individual& ind, const DataView& x, std::span<const double> y, const DataView& x_lm,
                std::span<const double> y_lm) const;

  SearchSettings settings_;
};

}  // namespace hs::regression
