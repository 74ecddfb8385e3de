// SPDX-License-Identifier: MIT
#include "resolved/measure/whole_revolutions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hs::resolved {

double WholeRevolutions::rate_rad_s() const {
  if (periods_s.empty() || window_end_s <= window_start_s) return 0.0;
  return 2.0 * std::numbers::pi * static_cast<double>(periods_s.size()) / (window_end_s - window_start_s);
}

bool WholeRevolutions::settled(double tolerance) const {
  if (periods_s.size() < 4) return false;
  const double last = periods_s[0] + periods_s[1];
  const double before = periods_s[2] + periods_s[3];
  return std::abs(last - before) <= tolerance * last;
}

namespace {

/// Mean of the samples with begin_s <= t < end_s (uniformly sampled); 0 without one.
double mean_between(std::span<const double> time_s, std::span<const double> value, double begin_s, double end_s) {
  double sum = 0.0, n = 0.0;
  for (std::size_t i = 0; i < std::min(time_s.size(), value.size()); ++i) {
    if (time_s[i] < begin_s || time_s[i] >= end_s) continue;
    sum += value[i];
    n += 1.0;
  }
  return n > 0.0 ? sum / n : 0.0;
}

}  // namespace

bool WholeRevolutions::settled(double tolerance, std::span<const double> time_s, std::span<const double> value) const {
  if (!settled(tolerance) || ends_s.size() < 5) return false;
  const double last = mean_between(time_s, value, ends_s[2], ends_s[0]);
  const double before = mean_between(time_s, value, ends_s[4], ends_s[2]);
  return std::abs(last - before) <= tolerance * std::abs(last);
}

WholeRevolutions whole_revolutions(std::span<const double> time_s, std::span<const double> phase_rad, std::size_t from) {
  WholeRevolutions r;
  const std::size_t n = std::min(time_s.size(), phase_rad.size());
  if (n < 2 || from + 1 >= n) return r;
  const double end_phase = phase_rad[n - 1];
  double end_s = time_s[n - 1];
  std::vector<double> ends{end_s};   // the end times of the revolutions, the last first
  int turns = 1;
  for (std::size_t i = n - 1; i > from; --i) {
    // Scanning back: the revolution `turns` ends (going back: begins) where |phase - end phase| reaches 2 pi turns.
    const double level = 2.0 * std::numbers::pi * turns;
    const double a = std::abs(phase_rad[i] - end_phase);
    const double b = std::abs(phase_rad[i - 1] - end_phase);
    if (a < level && b >= level) {
      const double w = (level - a) / (b - a);
      const double t = time_s[i] + w * (time_s[i - 1] - time_s[i]);
      r.periods_s.push_back(end_s - t);
      ends.push_back(t);
      end_s = t;
      ++turns;
    }
  }
  if (r.periods_s.empty()) return r;
  r.ends_s = ends;
  r.window_end_s = ends.front();
  r.window_start_s = ends.back();
  return r;
}

double keller_skalak_bound(double shear_rate_1_s, double deformation_index) {
  const double ratio = (1.0 + deformation_index) / (1.0 - deformation_index);
  return shear_rate_1_s * ratio / (1.0 + ratio * ratio);
}

}  // namespace hs::resolved
