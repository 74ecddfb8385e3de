// SPDX-License-Identifier: MIT
// The cancellation ratio: 1 for a sum of like-signed terms, large for a small difference of large terms.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "regression/cancellation.hpp"
#include "regression/data_view.hpp"
#include "regression/infix.hpp"

namespace hsr = hs::regression;

TEST(Cancellation, SmallDifferencesOfLargeTermsAreFlagged) {
  const std::vector<std::string> names{"x", "y"};
  std::vector<std::vector<double>> cols{{1.0, 2.0, 3.0, 4.0, 5.0}, {0.5, 1.0, 1.5, 2.0, 2.5}};
  const hsr::ColumnData data(cols);
  auto ratio = [&](const std::string& f) { return hsr::cancellation_ratio(hsr::parse_infix(f, names), data.view()); };
  EXPECT_DOUBLE_EQ(ratio("x*y"), 1.0);            // one term
  EXPECT_DOUBLE_EQ(ratio("x + y"), 1.0);          // like signs: nothing cancels
  // (1000 + x) - 1000 = x: the terms are (2000 + x)/x, median row x = 3 -> 2003/3.
  EXPECT_NEAR(ratio("(1000 + x) - 1000"), 2003.0 / 3.0, 1e-9);
  EXPECT_GT(ratio("(1000 + x) - 1000"), hsr::cancellation_warning_ratio);
  EXPECT_NEAR(ratio("x - y"), 3.0, 1e-12);        // x - x/2: terms 1.5 x, result 0.5 x
}
