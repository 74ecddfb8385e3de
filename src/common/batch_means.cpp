// SPDX-License-Identifier: MIT
// Batch means.
#include "common/batch_means.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::common {

MeanWithError batch_means(const std::vector<double>& x, int batches, std::size_t first) {
  if (batches < 2) throw std::invalid_argument("batch_means: needs at least 2 batches");
  const std::size_t n = x.size() > first ? x.size() - first : 0;
  const auto b = static_cast<std::size_t>(batches);
  if (n < b) throw std::invalid_argument("batch_means: fewer values than batches");
  const std::size_t len = n / b;
  const std::size_t start = x.size() - len * b;
  std::vector<double> means(b, 0.0);
  for (std::size_t k = 0; k < b; ++k) {
    for (std::size_t i = 0; i < len; ++i) means[k] += x[start + k * len + i];
    means[k] /= static_cast<double>(len);
  }
  double mean = 0.0;
  for (const double m : means) mean += m;
  mean /= static_cast<double>(b);
  double var = 0.0;
  for (const double m : means) var += (m - mean) * (m - mean);
  var /= static_cast<double>(b - 1);
  return {.mean = mean, .standard_error = std::sqrt(var / static_cast<double>(b)), .batches = batches};
}

std::vector<MeanWithError> batch_means(const std::vector<std::vector<double>>& x, int batches, std::size_t first) {
  std::vector<MeanWithError> out;
  if (x.empty()) return out;
  std::vector<double> column(x.size());
  for (std::size_t c = 0; c < x.front().size(); ++c) {
    for (std::size_t i = 0; i < x.size(); ++i) column[i] = x[i][c];
    out.push_back(batch_means(column, batches, first));
  }
  return out;
}

}  // namespace hs::common
