// SPDX-License-Identifier: MIT
// gplearn's program generation and variation operators on prefix expressions (gplearn/_program.py).
#pragma once

#include <cstddef>
#include <random>
#include <utility>

#include "regression/expression.hpp"
#include "regression/search_settings.hpp"

namespace hs::regression {

using Rng = std::mt19937_64;

class GeneticOperators {
 public:
  GeneticOperators(const SearchSettings& settings, std::size_t n_features);

  /// Ramped half-and-half: 'full' or 'grow' with p = 1/2, max depth uniform in [init_depth_lo, init_depth_hi];
  /// a terminal is a feature or (one chance in n_features + 1) a constant uniform in the const range.
  [[nodiscard]] Expression random_program(Rng& rng) const;
  /// Koza's choice of a subtree: functions weighted 0.9, terminals 0.1. Returns [start, end).
  [[nodiscard]] std::pair<std::size_t, std::size_t> random_subtree(const Expression& e, Rng& rng) const;

  [[nodiscard]] Expression crossover(const Expression& parent, const Expression& donor, Rng& rng) const;
  /// Crossover with a freshly generated program ("headless chicken").
  [[nodiscard]] Expression subtree_mutation(const Expression& parent, Rng& rng) const;
  /// A subtree replaced by one of its own subtrees (fights bloat).
  [[nodiscard]] Expression hoist_mutation(const Expression& parent, Rng& rng) const;
  /// Each node replaced with probability p_point_replace by a random node of the same arity.
  [[nodiscard]] Expression point_mutation(const Expression& parent, Rng& rng) const;

 private:
  [[nodiscard]] Node random_terminal(Rng& rng) const;
  [[nodiscard]] Op random_function(Rng& rng) const;
  [[nodiscard]] Op random_function_of_arity(int a, Rng& rng) const;
  void grow(std::vector<Node>& out, int depth, int max_depth, bool full, Rng& rng) const;

  SearchSettings settings_;
  std::size_t n_features_;
};

}  // namespace hs::regression
