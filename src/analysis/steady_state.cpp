// SPDX-License-Identifier: MIT
// MSER-5 truncation and the halves test.
#include "analysis/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/batch_means.hpp"

namespace hs::analysis {

SteadyStart mser_truncation(const std::vector<double>& x, int m) {
  const auto mm = static_cast<std::size_t>(m < 1 ? 1 : m);
  const std::size_t nb = x.size() / mm;
  if (nb < 4) return {};
  const std::size_t offset = x.size() - nb * mm;
  std::vector<double> b(nb, 0.0);
  for (std::size_t j = 0; j < nb; ++j) {
    for (std::size_t i = 0; i < mm; ++i) b[j] += x[offset + j * mm + i];
    b[j] /= static_cast<double>(mm);
  }
  // Two passes per d (not suffix sums of b and b^2, whose difference leaves round-off that decides the argmin of a
  // flat series): O(n_b^2 / 2), 1.5e6 operations for a run of 8800 steps.
  double best = std::numeric_limits<double>::infinity();
  std::size_t arg = 0;
  for (std::size_t d = 0; d <= nb / 2; ++d) {   // the first half only: at the end a few batches can look flat by chance
    const auto k = static_cast<double>(nb - d);
    double mean = 0.0;   // of b_j - b_d: a flat series gives exact zeros
    for (std::size_t j = d; j < nb; ++j) mean += b[j] - b[d];
    mean /= k;
    double ss = 0.0;
    for (std::size_t j = d; j < nb; ++j) ss += (b[j] - b[d] - mean) * (b[j] - b[d] - mean);
    const double mser = ss / (k * k);
    if (mser < best) {   // strict: a flat series keeps d = 0
      best = mser;
      arg = d;
    }
  }
  return {.found = arg < nb / 2, .start = offset + arg * mm};   // at the half's edge: still falling
}

HalvesTest halves_agree(const std::vector<double>& x, std::size_t start, double k, int batches, double relative_floor) {
  HalvesTest t;
  if (x.size() < start + 2 * static_cast<std::size_t>(batches)) return t;
  const std::size_t mid = start + (x.size() - start) / 2;
  const std::vector<double> first(x.begin() + static_cast<std::ptrdiff_t>(start), x.begin() + static_cast<std::ptrdiff_t>(mid));
  const hs::common::MeanWithError a = hs::common::batch_means(first, batches);
  const hs::common::MeanWithError b = hs::common::batch_means(x, batches, mid);
  t.first_mean = a.mean;
  t.second_mean = b.mean;
  t.combined_error = std::hypot(a.standard_error, b.standard_error);
  const double floor = relative_floor * std::max(std::abs(a.mean), std::abs(b.mean));
  t.agree = std::abs(b.mean - a.mean) <= std::max(k * t.combined_error, floor);
  return t;
}

}  // namespace hs::analysis
