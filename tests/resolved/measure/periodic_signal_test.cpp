// SPDX-License-Identifier: MIT
// Period detection and averaging on signals with known period and mean.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "resolved/measure/periodic_signal.hpp"

using namespace hs::resolved;

namespace {
std::vector<double> signal(double period, double dt, double duration, double mean, double amplitude, double transient = 0) {
  std::vector<double> s;
  for (double t = 0; t < duration; t += dt) {
    // A decaying transient plus a non-sinusoidal periodic part (two harmonics, as DI of a tumbling cell).
    s.push_back(mean + amplitude * (std::sin(2 * std::numbers::pi * t / period) + 0.3 * std::cos(4 * std::numbers::pi * t / period)) +
                transient * std::exp(-t / period));
  }
  return s;
}
}  // namespace

TEST(PeriodicSignal, DetectsThePeriod) {
  const double dt = 0.01;
  const auto s = signal(1.37, dt, 10.0, 0.2, 0.05);
  const auto p = detect_period(s, dt);
  ASSERT_TRUE(p.periodic);
  EXPECT_NEAR(p.period_s, 1.37, 0.5 * dt);   // parabolic refinement: better than one sample
}

TEST(PeriodicSignal, AveragesWholePeriodsToTheMean) {
  const double dt = 0.001;
  const auto s = signal(1.0, dt, 8.0, 0.2, 0.05);
  const auto p = detect_period(s, dt);
  const auto a = average_over_periods(s, dt, p, 3);
  EXPECT_EQ(a.periods, 3);
  // Whole periods of a zero-mean periodic part average to zero up to the boundary rounding of one sample.
  EXPECT_NEAR(a.mean, 0.2, 2e-4);
  EXPECT_LT(a.spread, 5e-4);
}

TEST(PeriodicSignal, SteadySignalIsRecognised) {
  const std::vector<double> s(100, 3.5);
  const auto p = detect_period(s, 0.1);
  EXPECT_TRUE(p.steady);
  const auto a = average_over_periods(s, 0.1, p, 3);
  EXPECT_DOUBLE_EQ(a.mean, 3.5);
  EXPECT_EQ(a.spread, 0.0);
}

TEST(PeriodicSignal, SettlesOnlyAfterTheTransient) {
  const double dt = 0.01;
  EXPECT_FALSE(has_settled(signal(1.0, dt, 3.0, 0.2, 0.05, 1.0), dt, 3, 0.0, 0.02));   // transient still in
  EXPECT_TRUE(has_settled(signal(1.0, dt, 12.0, 0.2, 0.05, 1.0), dt, 3, 0.5, 0.02));
}
