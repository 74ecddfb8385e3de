// SPDX-License-Identifier: MIT
// A benchmark's target as a check: below a floor (or above a ceiling) is exit 1, a value not measured is skipped
// (never a met target), and --tighten F moves the target by F.
#include <gtest/gtest.h>

#include <optional>

#include "bench/bench_targets.hpp"

using hs::bench::expect_at_least;
using hs::bench::expect_at_most;

TEST(BenchTargets, AFloorAndACeilingFailWhenMissed) {
  hs::common::CheckList checks;
  const hs::common::TaskOptions options;
  expect_at_least(checks, options, "roofline_fraction", 0.83, 0.82, "test");
  expect_at_most(checks, options, "s_per_step", 1.9, 2.0, "test");
  EXPECT_EQ(checks.exit_code(), 0);
  expect_at_least(checks, options, "speedup", 1.9, 2.0, "test");
  EXPECT_EQ(checks.exit_code(), 1);
}

TEST(BenchTargets, AnUnmeasuredValueIsSkippedNotMet) {
  hs::common::CheckList checks;
  expect_at_least(checks, hs::common::TaskOptions{}, "speedup_vs_liggghts", std::nullopt, 2.0, "test");
  EXPECT_EQ(checks.skipped(), 1);
  EXPECT_EQ(checks.failed(), 0);
}

TEST(BenchTargets, TightenMovesTheTargetPastTheValue) {
  hs::common::TaskOptions options;
  options.tighten = 1.1;
  hs::common::CheckList checks;
  expect_at_least(checks, options, "exact_full", 10.0, 10.0, "test");   // 10 >= 11? no
  expect_at_most(checks, options, "peak_GiB", 3.9, 4.0, "test");        // 3.9 <= 3.64? no
  EXPECT_EQ(checks.failed(), 2);
}
