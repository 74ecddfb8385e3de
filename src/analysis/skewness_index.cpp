// SPDX-License-Identifier: MIT
// The hematocrit skewness index S_H of a binned profile.
#include "analysis/skewness_index.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::analysis {

double skewness_index(const std::vector<double>& h) {
  const std::size_t n = h.size();
  double asymmetry = 0.0;
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (h[i] < 0.0) throw std::invalid_argument("skewness_index: a hematocrit below 0");
    asymmetry += std::abs(h[i] - h[n - 1 - i]);
    total += h[i];
  }
  return total > 0.0 ? asymmetry / total : 0.0;
}

}  // namespace hs::analysis
