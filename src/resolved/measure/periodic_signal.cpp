// SPDX-License-Identifier: MIT
// Period detection and whole-period averaging of a time series.
#include "resolved/measure/periodic_signal.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hs::resolved {

PeriodEstimate detect_period(std::span<const double> signal, double dt, double min_correlation) {
  PeriodEstimate out;
  const std::size_t n = signal.size();
  if (n < 8) return out;
  double mean = 0.0;
  for (double v : signal) mean += v;
  mean /= static_cast<double>(n);
  double var = 0.0;
  for (double v : signal) var += (v - mean) * (v - mean);
  // Constant to round-off (relative to the signal's magnitude): steady, nothing to detect.
  if (var <= static_cast<double>(n) * 1e-24 * std::max(1.0, mean * mean)) {
    out.steady = true;
    return out;
  }
  const std::size_t max_lag = n / 2;
  std::vector<double> r(max_lag + 1, 0.0);
  for (std::size_t k = 0; k <= max_lag; ++k) {
    double s = 0.0;
    for (std::size_t i = 0; i + k < n; ++i) s += (signal[i] - mean) * (signal[i + k] - mean);
    r[k] = s / var * static_cast<double>(n) / static_cast<double>(n - k);   // unbiased, normalised
  }
  std::size_t k = 1;
  while (k <= max_lag && r[k] > 0.0) ++k;   // first zero crossing
  if (k > max_lag) return out;
  // Multiples of the period correlate as well as the period itself: take the first local maximum that
  // reaches 90% of the highest peak, not the highest one.
  double highest = -1.0;
  for (std::size_t j = k; j < max_lag; ++j) highest = std::max(highest, r[j]);
  std::size_t best = max_lag;
  for (std::size_t j = k; j < max_lag; ++j) {
    if (r[j] >= r[j - 1] && r[j] >= r[j + 1] && r[j] >= 0.9 * highest) {
      best = j;
      break;
    }
  }
  out.correlation = r[best];
  if (r[best] < min_correlation || best == max_lag) return out;
  double lag = static_cast<double>(best);
  const double a = r[best - 1], b = r[best], c = r[best + 1];
  const double denom = a - 2.0 * b + c;
  if (denom < 0.0) lag += 0.5 * (a - c) / denom;
  out.periodic = true;
  out.period_s = lag * dt;
  return out;
}

PeriodAverage average_over_periods(std::span<const double> signal, double dt, const PeriodEstimate& period, int periods) {
  PeriodAverage out;
  const std::size_t n = signal.size();
  if (n == 0) return out;
  auto window_mean = [&](std::size_t begin, std::size_t end) {
    double s = 0.0;
    for (std::size_t i = begin; i < end; ++i) s += signal[i];
    return s / static_cast<double>(end - begin);
  };
  if (!period.periodic) {
    const std::size_t begin = n - std::max<std::size_t>(1, n / 4);
    out.steady = true;
    out.mean = window_mean(begin, n);
    const auto [lo, hi] = std::minmax_element(signal.begin() + static_cast<std::ptrdiff_t>(begin), signal.end());
    out.spread = *hi - *lo;
    return out;
  }
  out.period_s = period.period_s;
  const double samples_per_period = period.period_s / dt;
  const int available = static_cast<int>(static_cast<double>(n) / samples_per_period);
  out.periods = std::max(0, std::min(periods, available));
  if (out.periods == 0) {
    out.mean = window_mean(0, n);
    return out;
  }
  // Period j covers [end - (j+1) P, end - j P): boundaries rounded to samples, whole periods only.
  double total = 0.0, lo = HUGE_VAL, hi = -HUGE_VAL;
  std::size_t count = 0;
  for (int j = 0; j < out.periods; ++j) {
    const auto end = static_cast<std::size_t>(std::llround(static_cast<double>(n) - j * samples_per_period));
    const auto begin = static_cast<std::size_t>(std::llround(static_cast<double>(n) - (j + 1) * samples_per_period));
    const double m = window_mean(begin, end);
    lo = std::min(lo, m);
    hi = std::max(hi, m);
    for (std::size_t i = begin; i < end; ++i) total += signal[i];
    count += end - begin;
  }
  out.mean = total / static_cast<double>(count);
  out.spread = hi - lo;
  return out;
}

bool has_settled(std::span<const double> signal, double dt, int periods, double transient_fraction, double relative_spread,
                 double floor) {
  const auto skip = static_cast<std::size_t>(transient_fraction * static_cast<double>(signal.size()));
  const auto tail = signal.subspan(skip);
  const PeriodEstimate p = detect_period(tail, dt);
  if (p.steady) return tail.size() >= 8;
  if (!p.periodic) return false;
  const PeriodAverage a = average_over_periods(tail, dt, p, periods);
  return a.periods >= periods && a.spread <= relative_spread * std::max({std::abs(a.mean), floor, 1e-300});
}

}  // namespace hs::resolved
