// SPDX-License-Identifier: MIT
// Semi-dynamic epsilon-lexicase parent selection (La Cava, Spector & McPhee 2016), an alternative to tournaments.
#pragma once

#include <cstddef>
#include <vector>

#include "regression/genetic_operators.hpp"

namespace hs::regression {

class LexicaseSelector {
 public:
  /// errors[i]: absolute errors of individual i on the selection cases; eligible[i] false excludes it.
  /// epsilon per case = median absolute deviation of that case's errors over the eligible individuals.
  LexicaseSelector(std::vector<const std::vector<double>*> errors, const std::vector<bool>& eligible);

  /// Cases in random order; keep the individuals within epsilon of the best on each case until one is
  /// left (or the cases run out: then a random survivor).
  [[nodiscard]] std::size_t select(Rng& rng) const;

 private:
  std::vector<const std::vector<double>*> errors_;
  std::vector<std::size_t> pool_;
  std::vector<double> epsilon_;
};

}  // namespace hs::regression
