// SPDX-License-Identifier: MIT
// Rigid-sphere baselines: limits, hand values, and the reference tables in tests/data/closures (STYLE R9).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "closures/register_builtin.hpp"
#include "closures/saffman_mei_lift.hpp"
#include "closures/schiller_naumann.hpp"
#include "closures/stokes_drag.hpp"

namespace hc = hs::closures;

TEST(SchillerNaumann, ReducesToStokesAtLowReynolds) {
  // 0.15 * (1e-6)^0.687 ~ 1.2e-5: the correction is 1 to that accuracy.
  EXPECT_NEAR(hc::SchillerNaumann{}.correction({.re_p = 1e-6}), 1.0, 2e-5);
}

TEST(SchillerNaumann, HandValueAtReOne) {   // 1 + 0.15 * 1^0.687 = 1.15 exactly
  EXPECT_DOUBLE_EQ(hc::SchillerNaumann{}.correction({.re_p = 1.0}), 1.15);
  EXPECT_DOUBLE_EQ(hc::SchillerNaumann{}.drag_coefficient({.re_p = 1.0}), 24.0 * 1.15);
}

TEST(StokesDrag, CorrectionIsOneEverywhereAndCountsOutsideValidity) {
  const hc::StokesDrag s;
  EXPECT_EQ(s.correction({.re_p = 0.0}), 1.0);
  EXPECT_EQ(s.correction({.re_p = 5.0}), 1.0);   // outside [0, 1]
  EXPECT_EQ(s.evaluations(), 2);
  EXPECT_EQ(s.outside_validity(), 1);
  EXPECT_NE(s.usage_report().find("1 (50.00%) outside validity"), std::string::npos) << s.usage_report();
}

TEST(SaffmanMeiLift, MeiFactorTendsToOneForSmallReAndLargeShear) {
  // Mei (1992): at Re_p -> 0 the factor -> 1 (Saffman's law), whatever beta.
  EXPECT_NEAR(hc::SaffmanMeiLift::mei_factor(1e-9, 1e-9), 1.0, 1e-9);
}

namespace {

struct Row {
  std::vector<double> values;
};

std::vector<Row> read_reference(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);   // header
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string cell;
    Row r;
    while (std::getline(s, cell, ',')) {
      try {
        r.values.push_back(std::stod(cell));
      } catch (const std::exception&) {
        break;   // the source column
      }
    }
    rows.push_back(r);
  }
  return rows;
}

const std::filesystem::path data_dir = std::filesystem::path(HS_SOURCE_DIR) / "tests/data/closures";

}  // namespace

// Reference values were computed independently (python, from the published formulas). 1e-12 relative:
// only the order of floating-point operations differs.
TEST(ReferenceTables, DragBaselines) {
  for (const char* model : {"stokes", "schiller_naumann"}) {
    const auto rows = read_reference(data_dir / (std::string(model) + ".csv"));
    ASSERT_GE(rows.size(), 5u) << model;
    const auto closure = hc::make_drag_closure({.model = model, .file = {}});
    for (const auto& r : rows) {
      const hc::DragInputs in{.re_p = r.values[0], .re_shear = r.values[1]};
      EXPECT_NEAR(closure->drag_coefficient(in), r.values[2], 1e-12 * r.values[2]) << model << " Re_p=" << r.values[0];
      EXPECT_NEAR(closure->correction(in), r.values[3], 1e-12 * r.values[3]) << model << " Re_p=" << r.values[0];
    }
  }
}

TEST(ReferenceTables, LiftBaselines) {
  const auto rows = read_reference(data_dir / "saffman_mei.csv");
  ASSERT_GE(rows.size(), 5u);
  const auto closure = hc::make_lift_closure({.model = "saffman_mei", .file = {}});
  for (const auto& r : rows) {
    const hc::LiftInputs in{.re_p = r.values[0], .re_shear = r.values[1]};
    EXPECT_NEAR(closure->lift_coefficient(in), r.values[2], 1e-12 * r.values[2]) << "Re_p=" << r.values[0];
  }
}

TEST(Registry, UnknownModelNamesTheKnownOnes) {
  try {
    (void)hc::make_drag_closure({.model = "schiller", .file = {}});
    FAIL();
  } catch (const hs::common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("schiller_naumann"), std::string::npos) << e.what();
  }
}
