// SPDX-License-Identifier: MIT
// Reference tier for learned closures (STYLE R9): every committed closure still reproduces the table written
// when it was fitted, so a change to the parser or evaluator cannot quietly change a closure.
// A regression guard, not evidence of agreement: the tables are the closures' own output when fitted.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "closures/closure_check.hpp"

namespace fs = std::filesystem;

TEST(RegressionGuardLearnedReferenceTables, EveryCommittedClosureReproducesItsTable) {
  int checked = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(HS_SOURCE_DIR) / "data/closures")) {
    if (entry.path().extension() != ".toml") continue;
    std::string summary;
    ASSERT_NO_THROW(summary = hs::closures::check_closure(entry.path())) << entry.path();
    EXPECT_NE(summary.find("reproduces its reference table"), std::string::npos) << summary;
    ++checked;
  }
  EXPECT_GE(checked, 3);
}
