// SPDX-License-Identifier: MIT
// Binning across a channel cut.
#include "analysis/cut_profile.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::analysis {

int profile_bin(double w, int bins) {
  if (!(w >= 0.0 && w <= 1.0) || bins < 1) return -1;
  const int i = static_cast<int>(std::floor(w * bins));
  return i < bins ? i : bins - 1;
}

std::vector<double> hematocrit_profile(const std::vector<double>& rbc, const std::vector<double>& fluid) {
  if (rbc.size() != fluid.size()) throw std::invalid_argument("hematocrit_profile: sizes differ");
  std::vector<double> h(rbc.size(), 0.0);
  for (std::size_t i = 0; i < rbc.size(); ++i) h[i] = fluid[i] > 0.0 ? rbc[i] / fluid[i] : 0.0;
  return h;
}

}  // namespace hs::analysis
