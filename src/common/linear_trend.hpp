// SPDX-License-Identifier: MIT
// The least-squares straight line through a time series: how much a quantity still drifts over a window.
#pragma once

#include <algorithm>
#include <limits>

namespace hs::common {

/// Accumulates samples (t, y) and gives the least-squares line y = mean + slope (t - t_mean). Why: "steady" is
/// judged on the trend over the whole averaging window (issue #25), which noise between samples does not trip as
/// easily as a comparison of two halves, and which says how far the quantity would still move.
class LinearTrend {
 public:
  void add(double t, double y) {
    ++n_;
    const double dt = t - t_mean_;   // Welford-style running means and co-moments
    t_mean_ += dt / static_cast<double>(n_);
    const double dy = y - y_mean_;
    y_mean_ += dy / static_cast<double>(n_);
    s_tt_ += dt * (t - t_mean_);
    s_ty_ += dt * (y - y_mean_);
    t_min_ = std::min(t_min_, t);
    t_max_ = std::max(t_max_, t);
  }
  [[nodiscard]] long count() const { return n_; }
  [[nodiscard]] double mean() const { return y_mean_; }
  /// dy/dt of the fitted line (0 with fewer than two distinct times).
  [[nodiscard]] double slope() const { return s_tt_ > 0.0 ? s_ty_ / s_tt_ : 0.0; }
  /// The change of the fitted line from the first to the last sample time.
  [[nodiscard]] double change_over_window() const { return n_ > 1 ? slope() * (t_max_ - t_min_) : 0.0; }

 private:
  long n_ = 0;
  double t_mean_ = 0.0, y_mean_ = 0.0, s_tt_ = 0.0, s_ty_ = 0.0;
  double t_min_ = std::numeric_limits<double>::infinity(), t_max_ = -std::numeric_limits<double>::infinity();
};

}  // namespace hs::common
