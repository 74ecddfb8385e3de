// SPDX-License-Identifier: MIT
// The bifurcation study's statistics (analysis/) against analytic cases: S_H of uniform, symmetric and linear
// profiles, exact histogram counts, the MSER-5 start of a step and a ramp (batch means: tests/common/batch_means_test.cpp).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/cut_profile.hpp"
#include "analysis/histogram.hpp"
#include "analysis/skewness_index.hpp"
#include "analysis/steady_state.hpp"

namespace hs::analysis {
namespace {

TEST(SkewnessIndex, UniformAndSymmetricProfilesAreZero) {
  EXPECT_EQ(skewness_index(std::vector<double>(10, 0.2)), 0.0);
  const std::vector<double> symmetric{0.0, 0.1, 0.3, 0.3, 0.1, 0.0};
  EXPECT_EQ(skewness_index(symmetric), 0.0);
  EXPECT_EQ(skewness_index(std::vector<double>(8, 0.0)), 0.0);   // no cells: 0, not NaN
}

TEST(SkewnessIndex, LinearProfileGivesItsSlope) {
  // H = H0 (1 + a (2w - 1)) at the bin centres: S_H = |a| (the integrals) for an even n, where the midpoint rule is
  // exact for |H(w) - H(1-w)| = 2 H0 |a| |2w - 1|; an odd n has the kink inside its middle bin: sum |2i + 1 - n| =
  // (n^2 - 1) / 2, so S_H = |a| (1 - 1/n^2). 1e-14: a few ulps of the sums.
  for (const int n : {2, 5, 10, 41}) {
    for (const double a : {-0.7, 0.25, 1.0}) {
      std::vector<double> h;
      for (int i = 0; i < n; ++i) h.push_back(0.3 * (1.0 + a * (2.0 * (i + 0.5) / n - 1.0)));
      const double exact = n % 2 == 0 ? std::abs(a) : std::abs(a) * (1.0 - 1.0 / (n * n));
      EXPECT_NEAR(skewness_index(h), exact, 1e-14) << "n = " << n << ", a = " << a;
    }
  }
}

TEST(SkewnessIndex, AllCellsOnOneSide) {
  // H = 1 on w < 1/2, 0 beyond: int |H(w) - H(1-w)| = 1, int H = 1/2: S_H = 2, the largest value.
  // Built value by value: on this machine's CPU, GCC 12 -march=native (AVX-512) turned the literal {1, 1, 0, 0}
  // into {1, 1, 1, 1} (measured; -mavx2 builds it right), which is not what this test is about.
  std::vector<double> one_side(4, 0.0);
  one_side[0] = 1.0;
  one_side[1] = 1.0;
  EXPECT_DOUBLE_EQ(skewness_index(one_side), 2.0);
  const std::vector<double> negative{0.1, -0.1};
  EXPECT_THROW((void)skewness_index(negative), std::invalid_argument);
}

TEST(CutProfile, BinsAndHematocrit) {
  EXPECT_EQ(profile_bin(0.0, 10), 0);
  EXPECT_EQ(profile_bin(0.0999, 10), 0);
  EXPECT_EQ(profile_bin(0.1, 10), 1);
  EXPECT_EQ(profile_bin(1.0, 10), 9);
  EXPECT_EQ(profile_bin(-1e-12, 10), -1);
  EXPECT_EQ(profile_bin(1.0 + 1e-12, 10), -1);
  const auto h = hematocrit_profile({1.0, 0.0, 3.0}, {4.0, 2.0, 0.0});
  EXPECT_EQ(h, (std::vector<double>{0.25, 0.0, 0.0}));   // an empty bin (no fluid) reads 0
}

TEST(UniformHistogram, CountsAreExact) {
  UniformHistogram h(0.4, 0.6, 40);   // bins of 0.005, as the study's case files
  for (const double x : {0.39, 0.40, 0.4049, 0.405, 0.5, 0.5049, 0.505, 0.6, 0.61}) h.add(x);
  EXPECT_EQ(h.below(), 1);
  EXPECT_EQ(h.above(), 1);
  EXPECT_EQ(h.total(), 9);
  EXPECT_EQ(h.counts()[0], 2);    // 0.40 and 0.4049
  EXPECT_EQ(h.counts()[1], 1);    // 0.405
  EXPECT_EQ(h.counts()[20], 2);   // 0.5 and 0.5049
  EXPECT_EQ(h.counts()[21], 1);   // 0.505
  EXPECT_EQ(h.counts()[39], 1);   // 0.6, the upper end, in the last bin
  // Above 0.505 (a bin edge): 0.505, 0.6 and 0.61 of 9 values.
  EXPECT_DOUBLE_EQ(h.fraction_above(0.505), 3.0 / 9.0);
  UniformHistogram g(0.4, 0.6, 40);
  g.add(0.5, 7);
  h.add(g);
  EXPECT_EQ(h.counts()[20], 9);
  EXPECT_NEAR(g.binned_mean(), 0.5025, 1e-15);   // the bin centre
  EXPECT_THROW(h.add(UniformHistogram(0.0, 1.0, 40)), std::invalid_argument);
}

TEST(SteadyState, StepSettlesWhereItEnds) {
  // 200 values of a transient decaying from 1 then 800 of noise around 0: MSER-5 starts within the last part of the
  // transient (its batches of 5: within 10 values of 200, where the decay has fallen below the noise).
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 0.05);
  std::vector<double> x;
  for (int i = 0; i < 1000; ++i) x.push_back((i < 200 ? 1.0 - i / 200.0 : 0.0) + g(rng));
  const auto s = mser_truncation(x);
  EXPECT_TRUE(s.found);
  EXPECT_GT(s.start, 150u);
  EXPECT_LT(s.start, 260u);
  EXPECT_TRUE(halves_agree(x, s.start).agree);
}

TEST(SteadyState, RampNeverSettles) {
  // A ramp with small noise: the smallest MSER lies at the end (the fewest, closest values): not found, and its
  // halves differ by 25% of the rise against a standard error of ~0.1%.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 0.01);
  std::vector<double> x;
  for (int i = 0; i < 1000; ++i) x.push_back(i / 1000.0 + g(rng));
  EXPECT_FALSE(mser_truncation(x).found);
  EXPECT_FALSE(halves_agree(x, 0).agree);
  EXPECT_FALSE(halves_agree(x, 0, 3.0, 5, 0.01).agree);   // a 1% floor does not hide a 50% drift
  EXPECT_TRUE(halves_agree(std::vector<double>(100, 2.0), 0).agree);   // constant: no error, no difference
  EXPECT_FALSE(mser_truncation({1.0, 2.0, 3.0}).found);                // too short to judge
  const auto flat = mser_truncation(std::vector<double>(1000, 0.3));  // settled from the start
  EXPECT_TRUE(flat.found);
  EXPECT_EQ(flat.start, 0u);
}

}  // namespace
}  // namespace hs::analysis
