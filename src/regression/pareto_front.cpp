// SPDX-License-Identifier: MIT
// Best-per-complexity archive and its non-dominated subset.
#include "regression/pareto_front.hpp"

#include <cmath>

namespace hs::regression {

void ParetoFront::offer(ParetoEntry entry) {
  if (!std::isfinite(entry.loss)) return;
  auto it = best_.find(entry.complexity);
  if (it == best_.end()) {
    best_.emplace(entry.complexity, std::move(entry));
  } else if (entry.loss < it->second.loss) {
    it->second = std::move(entry);
  }
}

std::vector<ParetoEntry> ParetoFront::front() const {
  std::vector<ParetoEntry> out;
  for (const auto& [complexity, entry] : best_) {
    if (out.empty() || entry.loss < out.back().loss) out.push_back(entry);
  }
  return out;
}

}  // namespace hs::regression
