// SPDX-License-Identifier: MIT
// The Pareto front of model complexity (node count) versus error, kept across generations.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

struct ParetoEntry {
  std::size_t complexity = 0;   // nodes of the simplified expression
  double loss = 0.0;            // training loss (the search metric)
  Expression expression;        // simplified, with any scaling folded in
  double cv_loss = -1.0;        // filled in by cross-validation (< 0: not computed)
};

class ParetoFront {
 public:
  /// Keeps `entry` if it has the lowest loss seen at its complexity (ties keep the first, so the result does
  /// not depend on the order threads finish in: callers offer in a fixed order).
  void offer(ParetoEntry entry);
  /// The non-dominated entries, by increasing complexity (each strictly better than all simpler ones).
  [[nodiscard]] std::vector<ParetoEntry> front() const;
  [[nodiscard]] bool empty() const { return best_.empty(); }

 private:
  std::map<std::size_t, ParetoEntry> best_;
};

}  // namespace hs::regression
