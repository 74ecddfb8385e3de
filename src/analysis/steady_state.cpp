// SPDX-License-Identifier: MIT
// MSER-5 truncation and the halves test.
#include "analysis/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/batch_means.hpp"

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
  // Suffix sums give each MSER(d) in O(1).
  std::vector<double> s1(nb + 1, 0.0);
  std::vector<double> s2(nb + 1, 0.0);
  for (std::size_t j = nb; j-- > 0;) {
    s1[j] = s1[j + 1] + b[j];
    s2[j] = s2[j + 1] + b[j] * b[j];
  }
  double best = std::numeric_limits<double>::infinity();
  std::size_t arg = 0;
  for (std::size_t d = 0; d <= nb / 2; ++d) {   // the first half only: at the end a few batches can look flat by chance
    const auto k = static_cast<double>(nb - d);
    const double ss = std::max(0.0, s2[d] - s1[d] * s1[d] / k);
    const double mser = ss / (k * k);
    if (mser < best) {
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
  const MeanWithError a = batch_means(first, batches);
  const MeanWithError b = batch_means(x, batches, mid);
  t.first_mean = a.mean;
  t.second_mean = b.mean;
  t.combined_error = std::hypot(a.standard_error, b.standard_error);
  const double floor = relative_floor * std::max(std::abs(a.mean), std::abs(b.mean));
  t.agree = std::abs(b.mean - a.mean) <= std::max(k * t.combined_error, floor);
  return t;
}

}  // namespace hs::analysis
