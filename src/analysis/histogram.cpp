// SPDX-License-Identifier: MIT
// A histogram of equal bins.
#include "analysis/histogram.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::analysis {

UniformHistogram::UniformHistogram(double lo, double hi, int bins) : lo_(lo), hi_(hi) {
  if (!(hi > lo) || bins < 1) throw std::invalid_argument("UniformHistogram: needs hi > lo and bins >= 1");
  counts_.assign(static_cast<std::size_t>(bins), 0);
}

int UniformHistogram::bin_of(double x) const {
  if (x < lo_) return -1;
  if (x > hi_) return bins();
  const int i = static_cast<int>(std::floor((x - lo_) / (hi_ - lo_) * bins()));
  return i < bins() ? i : bins() - 1;   // x = hi
}

void UniformHistogram::add(double x, std::int64_t count) {
  const int i = bin_of(x);
  if (i < 0) {
    below_ += count;
  } else if (i >= bins()) {
    above_ += count;
  } else {
    counts_[static_cast<std::size_t>(i)] += count;
  }
}

void UniformHistogram::add(const UniformHistogram& other) {
  if (other.bins() != bins() || other.lo_ != lo_ || other.hi_ != hi_) {
    throw std::invalid_argument("UniformHistogram::add: different bins");
  }
  for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
  below_ += other.below_;
  above_ += other.above_;
}

double UniformHistogram::bin_centre(int i) const { return lo_ + (i + 0.5) * (hi_ - lo_) / bins(); }

std::int64_t UniformHistogram::total() const {
  std::int64_t n = below_ + above_;
  for (const auto c : counts_) n += c;
  return n;
}

double UniformHistogram::fraction_above(double threshold) const {
  const std::int64_t n = total();
  if (n == 0) return 0.0;
  std::int64_t above = above_;
  for (int i = 0; i < bins(); ++i) {
    if (bin_centre(i) > threshold) above += counts_[static_cast<std::size_t>(i)];
  }
  if (threshold < lo_) above += below_;
  return static_cast<double>(above) / static_cast<double>(n);
}

double UniformHistogram::binned_mean() const {
  double sum = 0.0;
  std::int64_t n = 0;
  for (int i = 0; i < bins(); ++i) {
    sum += bin_centre(i) * static_cast<double>(counts_[static_cast<std::size_t>(i)]);
    n += counts_[static_cast<std::size_t>(i)];
  }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace hs::analysis
