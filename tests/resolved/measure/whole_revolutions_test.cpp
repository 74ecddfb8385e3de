// SPDX-License-Identifier: MIT
// Whole revolutions of a marker on synthetic phases with known periods; the Keller-Skalak bound's limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "resolved/measure/whole_revolutions.hpp"

using namespace hs::resolved;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Series {
  std::vector<double> t, phase;
};

/// A marker turning clockwise at `rate` with a non-uniform speed (a tank-treading membrane on an elongated shape),
/// sampled every `dt` up to `end`.
Series marker(double rate, double end, double dt, double wobble) {
  Series s;
  for (double t = 0.0; t <= end + 1e-12; t += dt) {
    s.t.push_back(t);
    s.phase.push_back(-(rate * t + wobble * std::sin(2.0 * rate * t)));
  }
  return s;
}
}  // namespace

TEST(WholeRevolutions, PeriodsOfAUniformMarkerAreExactAndSettled) {
  const double rate = 50.0;   // rad/s: period 0.12566 s
  const Series s = marker(rate, 1.2, 1e-4, 0.0);
  const WholeRevolutions r = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  // 0.6 s after the transient half: 4 whole revolutions of 0.1257 s.
  ASSERT_EQ(r.periods_s.size(), 4u);
  for (const double p : r.periods_s) EXPECT_NEAR(p, kTwoPi / rate, 1e-9);   // linear interpolation of a linear phase
  EXPECT_NEAR(r.rate_rad_s(), rate, 1e-7);
  EXPECT_NEAR(r.window_end_s, 1.2, 1e-12);
  EXPECT_NEAR(r.window_start_s, 1.2 - 4.0 * kTwoPi / rate, 1e-9);
  EXPECT_TRUE(r.settled(0.02));
}

TEST(WholeRevolutions, ANonUniformSpeedAveragesOutOverWholeRevolutions) {
  // The speed varies by +-60 % along a revolution, yet a whole revolution takes exactly 2 pi / rate: a window of
  // whole revolutions measures the mean rate, where a window ending mid-revolution would not.
  const double rate = 40.0;
  const Series s = marker(rate, 1.5, 1e-4, 0.3);
  const WholeRevolutions r = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  ASSERT_GE(r.periods_s.size(), 4u);
  EXPECT_NEAR(r.rate_rad_s(), rate, 1e-3 * rate);   // interpolation error of a curved phase at 1e-4 s sampling
  EXPECT_TRUE(r.settled(0.02));
}

TEST(WholeRevolutions, JitterWithoutATrendIsSettledWhereATrendIsNot) {
  // Revolutions alternately 4 % shorter and longer than 0.1 s (the jitter of one marker vertex): pairs agree.
  Series s;
  double phase = 0.0;
  for (int k = 0; k < 12; ++k) {
    const double period = 0.1 * (k % 2 == 0 ? 0.96 : 1.04);
    for (int i = 0; i < 1000; ++i) {
      s.t.push_back(s.t.empty() ? 0.0 : s.t.back() + period / 1000.0);
      s.phase.push_back(phase + kTwoPi * i / 1000.0);
    }
    phase += kTwoPi;
  }
  const WholeRevolutions jitter = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  ASSERT_GE(jitter.periods_s.size(), 4u);
  EXPECT_GT(std::abs(jitter.periods_s[0] - jitter.periods_s[1]), 0.07 * jitter.periods_s[0]);
  EXPECT_TRUE(jitter.settled(0.02));
  EXPECT_NEAR(jitter.rate_rad_s(), kTwoPi / 0.1, 0.02 * kTwoPi / 0.1);
}

TEST(WholeRevolutions, AMarkerThatIsStillSpeedingUpIsNotSettled) {
  Series s;
  for (double t = 0.0; t <= 2.0; t += 1e-4) {   // rate 20 -> 60 rad/s over the run: the last two pairs differ by ~7 %
    s.t.push_back(t);
    s.phase.push_back(20.0 * t + 10.0 * t * t);
  }
  const WholeRevolutions r = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  ASSERT_GE(r.periods_s.size(), 4u);
  EXPECT_LT(r.periods_s[0], r.periods_s[1]);   // the last revolution is the fastest
  EXPECT_FALSE(r.settled(0.02));
}

TEST(WholeRevolutions, AShapeThatStillChangesIsNotSettledThoughItsPeriodsRepeat) {
  // Uniform revolutions (periods exact), DI swinging twice per revolution about a mean that is steady in one series
  // and falls by 2 % per revolution in the other (the swinging cell at 10.7 mPa s, Ca 2.04 lost ~3 % per revolution).
  const double rate = 50.0;
  const Series s = marker(rate, 1.2, 1e-4, 0.0);
  std::vector<double> steady, drifting;
  for (const double t : s.t) {
    const double swing = 0.05 * std::cos(2.0 * rate * t);
    steady.push_back(0.4 + swing);
    drifting.push_back(0.4 * std::pow(0.98, t * rate / kTwoPi) + swing);
  }
  const WholeRevolutions r = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  ASSERT_EQ(r.ends_s.size(), 5u);   // four whole revolutions: five ends
  EXPECT_TRUE(r.settled(0.02));
  EXPECT_TRUE(r.settled(0.02, s.t, steady));      // whole swings average out exactly (sampling aside)
  EXPECT_FALSE(r.settled(0.02, s.t, drifting));   // last pair 4 % below the pair before
  EXPECT_TRUE(r.settled(0.05, s.t, drifting));
}

TEST(WholeRevolutions, FewerThanFourRevolutionsAfterTheTransientAreNotSettled) {
  const Series s = marker(50.0, 1.0, 1e-4, 0.0);   // 3.98 revolutions in the second half
  const WholeRevolutions r = whole_revolutions(s.t, s.phase, s.t.size() / 2);
  EXPECT_EQ(r.periods_s.size(), 3u);
  EXPECT_GT(r.rate_rad_s(), 0.0);
  EXPECT_FALSE(r.settled(0.02));
  const Series slow = marker(10.0, 1.0, 1e-3, 0.0);   // 0.8 revolutions: none whole
  const WholeRevolutions none = whole_revolutions(slow.t, slow.phase, slow.t.size() / 2);
  EXPECT_TRUE(none.periods_s.empty());
  EXPECT_EQ(none.rate_rad_s(), 0.0);
}

TEST(KellerSkalakBound, IsHalfTheShearRateForASphereAndLowerForAnElongatedCell) {
  EXPECT_DOUBLE_EQ(keller_skalak_bound(600.0, 0.0), 300.0);   // a1 = a2
  // DI 0.5: a1 / a2 = 3, bound gamma 3 / 10.
  EXPECT_NEAR(keller_skalak_bound(600.0, 0.5), 180.0, 1e-9);
}
