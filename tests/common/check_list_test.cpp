// SPDX-License-Identifier: MIT
// A validation's verdict: any failed check fails it, a skipped check is listed and never counted as passed.
#include <gtest/gtest.h>

#include "common/check_list.hpp"

using hs::common::CheckList;

TEST(CheckList, AnyFailedCheckGivesExitOne) {
  CheckList checks;
  checks.expect("a", true, "");
  EXPECT_EQ(checks.exit_code(), 0);
  checks.expect("b", false, "12% vs 5%");
  EXPECT_EQ(checks.failed(), 1);
  EXPECT_EQ(checks.exit_code(), 1);
}

TEST(CheckList, SkippedChecksAreReportedNotPassed) {
  CheckList checks;
  checks.skip("band", "--quick");
  EXPECT_EQ(checks.exit_code(), 0);
  nlohmann::json j;
  checks.write_to(j);
  EXPECT_EQ(j["checks_skipped"], 1);
  EXPECT_EQ(j["checks"][0]["status"], "skipped");
  EXPECT_EQ(j["checks"][0]["detail"], "--quick");
  EXPECT_TRUE(j["passed"].get<bool>());
}
