// SPDX-License-Identifier: MIT
// Batch means (common/batch_means) on a known series and on white noise, whose standard error is known.
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "common/batch_means.hpp"

namespace hs::common {
namespace {

TEST(BatchMeans, KnownSeries) {
  // 1..20 in 4 batches of 5: means 3, 8, 13, 18; mean 10.5; sd of the means sqrt(41.667), SE sqrt(41.667 / 4).
  std::vector<double> x;
  for (int i = 1; i <= 20; ++i) x.push_back(i);
  const auto m = batch_means(x, 4);
  EXPECT_DOUBLE_EQ(m.mean, 10.5);
  EXPECT_NEAR(m.standard_error, std::sqrt(125.0 / 3.0 / 4.0), 1e-12);
  // The remainder is dropped at the front: 22 values in 4 batches use the last 20.
  x.insert(x.begin(), {100.0, 100.0});
  EXPECT_DOUBLE_EQ(batch_means(x, 4).mean, 10.5);
  EXPECT_DOUBLE_EQ(batch_means(x, 4, 2).mean, 10.5);
  EXPECT_THROW((void)batch_means(x, 1), std::invalid_argument);
  EXPECT_THROW((void)batch_means(std::vector<double>(3, 1.0), 4), std::invalid_argument);
}

TEST(BatchMeans, WhiteNoiseErrorMatchesTheory) {
  // Independent N(0, 1) values: SE of the mean 1 / sqrt(n) = 0.01 for n = 1e4; batch means over 20 batches
  // estimate it with a relative spread sqrt(1 / (2 * 19)) = 16%: 3 sigma is 50%.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> x(10000);
  for (double& v : x) v = g(rng);
  const auto m = batch_means(x, 20);
  EXPECT_NEAR(m.standard_error, 0.01, 0.005);
  EXPECT_NEAR(m.mean, 0.0, 3.0 * 0.01);
}

}  // namespace
}  // namespace hs::common
