// SPDX-License-Identifier: MIT
// A histogram of equal bins over [lo, hi], with the values outside counted apart (DI of a cell population).
#pragma once

#include <cstdint>
#include <vector>

namespace hs::analysis {

class UniformHistogram {
 public:
  /// pre: hi > lo, bins >= 1 (std::invalid_argument otherwise).
  UniformHistogram(double lo, double hi, int bins);

  /// Bin i holds lo + i w <= x < lo + (i+1) w (w = (hi - lo) / bins); x = hi goes to the last bin; x < lo counts
  /// as below, x > hi as above.
  void add(double x, std::int64_t count = 1);
  /// Adds another histogram's counts. pre: the same lo, hi and bins.
  void add(const UniformHistogram& other);

  [[nodiscard]] int bin_of(double x) const;   // -1 below, bins() above
  [[nodiscard]] int bins() const { return static_cast<int>(counts_.size()); }
  [[nodiscard]] double lo() const { return lo_; }
  [[nodiscard]] double hi() const { return hi_; }
  [[nodiscard]] double bin_centre(int i) const;
  [[nodiscard]] const std::vector<std::int64_t>& counts() const { return counts_; }
  [[nodiscard]] std::int64_t below() const { return below_; }
  [[nodiscard]] std::int64_t above() const { return above_; }
  /// Every value added, inside and outside [lo, hi].
  [[nodiscard]] std::int64_t total() const;
  /// Share of the values added that are > threshold, exact for values inside [lo, hi] when threshold is a bin edge
  /// (otherwise the bin holding it counts as above when its centre is); 0 when empty.
  [[nodiscard]] double fraction_above(double threshold) const;
  /// Mean of the values inside [lo, hi] at their bin centres (within half a bin width of the exact mean).
  [[nodiscard]] double binned_mean() const;

 private:
  double lo_;
  double hi_;
  std::vector<std::int64_t> counts_;
  std::int64_t below_ = 0;
  std::int64_t above_ = 0;
};

}  // namespace hs::analysis
