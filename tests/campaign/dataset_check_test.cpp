// SPDX-License-Identifier: MIT
// The resolved dataset's acceptance rules: each is caught on a row that breaks it, and the ranges are reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "campaign/dataset_check.hpp"
#include "common/errors.hpp"

namespace fs = std::filesystem;

namespace {

const char* kHeader =
    "re,r_star,cd,cd_settled,cd_spread,cl,cl_spread,di,di_spread,dx_m,flow_mode,gamma_plus,git_commit,periods,re_p,"
    "settled,u_r_plus\n";

/// A file of its own per test: ctest runs the tests of this binary as parallel processes.
fs::path temp_file(const std::string& suffix) {
  return fs::temp_directory_path() /
         ("hs_dataset_check_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + suffix);
}

fs::path write_dataset(const std::string& rows) {
  const fs::path file = temp_file(".csv");
  std::ofstream(file) << kHeader << rows;
  return file;
}

/// The seed paper's grid and ranges (the validation reads them from campaign.toml and data/reference).
hs::campaign::DatasetExpectations paper() {
  return {.re = {0.1, 0.2, 0.3, 0.4, 0.5}, .r_star = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7}, .gamma_plus = {0.02, 0.35},
          .re_p = {0.01, 0.12}};
}

std::string row(double re, double r_star, double cd, double cl, double di, const char* settled = "true") {
  // Cd Re_p = 36 at every Re (Stokes scaling); Re_p = 0.07 Re, gamma+ = 0.7 Re.
  return std::to_string(re) + "," + std::to_string(r_star) + "," + std::to_string(cd) + ",true,0.1," +
         std::to_string(cl) + ",0.01," + std::to_string(di) + ",1e-4,1e-06,intermediate," + std::to_string(0.7 * re) +
         ",abcdef0123,3," + std::to_string(0.07 * re) + "," + settled + ",-0.05\n";
}

}  // namespace

TEST(ResolvedDatasetCheck, AGoodPartialDatasetBreaksNoRuleButIsIncomplete) {
  const auto c = hs::campaign::check_resolved_dataset(
      write_dataset(row(0.5, 0.7, 36.0 / 0.035, -30.0, 0.48) + row(0.1, 0.7, 36.0 / 0.007, -70.0, 0.51, "false")), paper());
  EXPECT_EQ(c.rows, 2);
  EXPECT_EQ(c.rows_expected, 30);
  EXPECT_EQ(c.missing.size(), 28u);
  EXPECT_TRUE(c.problems.empty());
  EXPECT_FALSE(c.complete_and_valid());
  EXPECT_EQ(c.unsettled, 1);
  EXPECT_NEAR(c.gamma_plus.min, 0.07, 1e-12);
  EXPECT_NEAR(c.gamma_plus.max, 0.35, 1e-12);
  EXPECT_NEAR(c.re_p.max, 0.035, 1e-12);
  ASSERT_EQ(c.stokes.size(), 1u);
  EXPECT_NEAR(c.stokes[0].median, 36.0, 1e-3);
  EXPECT_LT(c.stokes[0].max_deviation, 1e-4);
}

TEST(ResolvedDatasetCheck, EachBrokenRuleIsNamedWithItsRow) {
  const auto c = hs::campaign::check_resolved_dataset(write_dataset(
      row(0.5, 0.7, 1000.0, -30.0, 1.2) +   // DI outside (0, 1)
      row(0.4, 0.7, -1000.0, -30.0, 0.5) +  // drag against the flow
      row(0.3, 0.7, 1000.0, 5.0, 0.5) +     // lift away from the axis
      "0.2,0.7,nan,true,0.1,-30,0.01,0.5,1e-4,1e-06,intermediate,0.14,abcdef0123,3,0.014,true,-0.05\n"), paper());
  ASSERT_EQ(c.problems.size(), 5u);   // the NaN Cd breaks "finite" and "along the flow"
  EXPECT_NE(c.problems[0].what.find("DI"), std::string::npos);
  EXPECT_DOUBLE_EQ(c.problems[0].re, 0.5);
  EXPECT_NE(c.problems[1].what.find("Cd"), std::string::npos);
  EXPECT_NE(c.problems[2].what.find("Cl"), std::string::npos);
  EXPECT_NE(c.problems[3].what.find("cd is not a finite number"), std::string::npos);
  // The broken values stay out of the ranges and the Stokes groups.
  EXPECT_DOUBLE_EQ(c.cd.min, -1000.0);
  EXPECT_DOUBLE_EQ(c.cd.max, 1000.0);
  ASSERT_EQ(c.stokes.size(), 1u);
  EXPECT_EQ(c.stokes[0].rows, 2);   // the negative Cd and the NaN are not drag values to scale
}

TEST(ResolvedDatasetCheck, CrlfLinesStillCountUnsettledRows) {
  const std::string r = row(0.5, 0.7, 1000.0, -30.0, 0.5, "false");
  const auto c = hs::campaign::check_resolved_dataset(write_dataset(r.substr(0, r.size() - 1) + "\r\n"), paper());
  EXPECT_EQ(c.unsettled, 1);
}

TEST(ResolvedDatasetCheck, ReadsThePaperRangesFromTheReferenceFile) {
  hs::campaign::DatasetExpectations e;
  hs::campaign::read_published_ranges(fs::path(HS_SOURCE_DIR) / "data/reference/porcaro2026_dataset_ranges.csv", e);
  EXPECT_DOUBLE_EQ(e.gamma_plus.min, 0.02);
  EXPECT_DOUBLE_EQ(e.gamma_plus.max, 0.35);
  EXPECT_DOUBLE_EQ(e.re_p.min, 0.01);
  EXPECT_DOUBLE_EQ(e.re_p.max, 0.12);
  const fs::path bad = temp_file(".csv");
  std::ofstream(bad) << "quantity,min,max\ngamma_plus,0.02,0.35\n";
  EXPECT_THROW(hs::campaign::read_published_ranges(bad, e), hs::common::ConfigError);
}

TEST(ResolvedDatasetCheck, AMissingColumnIsABadInput) {
  const fs::path file = temp_file(".csv");
  std::ofstream(file) << "re,r_star,cd\n0.5,0.7,1000\n";
  EXPECT_THROW(hs::campaign::check_resolved_dataset(file, paper()), hs::common::ConfigError);
}
