// SPDX-License-Identifier: MIT
// Learned closures evaluate their expression on the inputs they declare and count out-of-range use.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "closures/register_builtin.hpp"

namespace fs = std::filesystem;
namespace hc = hs::closures;

namespace {

fs::path drag_file() {
  // One file per test: CTest runs the tests of this binary in parallel, and two writing one file race.
  const fs::path p = fs::temp_directory_path() /
                     (std::string("hs_learned_drag_") + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".toml");
  std::ofstream(p) << "name = \"cd\"\nkind = \"drag\"\noutput = \"C_d\"\nexpression = \"24/re_p*(1 + 0.5*di)\"\n"
                      "[variables]\nre_p = \"Re_p\"\ndi = \"DI\"\n[validity]\nre_p = [0.01, 0.12]\ndi = [0.1, 0.5]\n";
  return p;
}

}  // namespace

TEST(ExpressionDrag, EvaluatesTheFormulaAndItsCorrection) {
  const auto drag = hc::make_drag_closure({.model = "expression", .file = drag_file()});
  const hc::DragInputs in{.re_p = 0.05, .di = 0.3};
  EXPECT_DOUBLE_EQ(drag->drag_coefficient(in), 24.0 / 0.05 * (1.0 + 0.5 * 0.3));
  EXPECT_DOUBLE_EQ(drag->correction(in), 24.0 / 0.05 * (1.0 + 0.5 * 0.3) * 0.05 / 24.0);
  EXPECT_EQ(drag->name(), "cd");
}

TEST(ExpressionDrag, CountsEvaluationsOutsideValidityFromManyThreads) {
  const auto drag = hc::make_drag_closure({.model = "expression", .file = drag_file()});
  std::vector<std::thread> pool;
  for (int t = 0; t < 4; ++t) {
    pool.emplace_back([&drag] {
      for (int i = 0; i < 1000; ++i) {
        (void)drag->drag_coefficient({.re_p = i % 2 == 0 ? 0.05 : 0.5, .di = 0.3});   // every other one outside
      }
    });
  }
  for (auto& t : pool) t.join();
  EXPECT_EQ(drag->evaluations(), 4000);
  EXPECT_EQ(drag->outside_validity(), 2000);
}

TEST(ExpressionDrag, OutsideItsValidityItClampsOrExtrapolatesAsAsked) {
  // re_p = 0.5 lies beyond the box [0.01, 0.12]: clamped, the correction C_d Re_p / 24 is the formula's at the box
  // edge (re_p 0.12, di 0.1), so C_d = C_d(edge) x 0.12 / 0.5; extrapolated, the formula at 0.5.
  const auto clamped = hc::make_drag_closure({.model = "expression", .file = drag_file()});
  const auto raw = hc::make_drag_closure({.model = "expression", .file = drag_file(), .outside = hc::OutsideValidity::extrapolate});
  const hc::DragInputs in{.re_p = 0.5, .di = 0.05};
  EXPECT_DOUBLE_EQ(clamped->drag_coefficient(in), 24.0 / 0.12 * (1.0 + 0.5 * 0.1) * 0.12 / 0.5);
  EXPECT_DOUBLE_EQ(raw->drag_coefficient(in), 24.0 / 0.5 * (1.0 + 0.5 * 0.05));
  EXPECT_EQ(clamped->outside_validity(), 1);   // counted either way
  EXPECT_EQ(raw->outside_validity(), 1);
  EXPECT_DOUBLE_EQ(clamped->correction(in), 24.0 / 0.12 * (1.0 + 0.5 * 0.1) * 0.12 / 24.0);
  // The drag correction C_d Re_p / 24 keeps its edge value: at a slip far below the box the drag stays Stokes-like.
  const hc::DragInputs slow{.re_p = 1e-5, .di = 0.3};
  EXPECT_DOUBLE_EQ(clamped->correction(slow), 24.0 / 0.01 * (1.0 + 0.5 * 0.3) * 0.01 / 24.0);
}

TEST(ExpressionLift, ClampedBelowItsShearBoxTheLiftFadesToZeroOnTheAxis) {
  // C_l = 2 gamma+ - 0.5 on gamma+ in [0.1, 0.3]: at the box edge -0.3; below it, clamped, -0.3 x gamma+ / 0.1
  // (the lift is odd in r, gamma+ linear in r); extrapolated, the formula itself.
  const fs::path p = fs::temp_directory_path() / "hs_learned_lift.toml";
  std::ofstream(p) << "name = \"cl\"\nkind = \"lift\"\noutput = \"C_l\"\nexpression = \"2*gamma_plus - 0.5\"\n"
                      "[variables]\ngamma_plus = \"gamma+\"\n[validity]\ngamma_plus = [0.1, 0.3]\n";
  const auto clamped = hc::make_lift_closure({.model = "expression", .file = p});
  const auto raw = hc::make_lift_closure({.model = "expression", .file = p, .outside = hc::OutsideValidity::extrapolate});
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.gamma_plus = 0.2}), -0.1);          // inside: the formula
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.gamma_plus = 0.05}), -0.3 * 0.5);   // half way to the axis
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.gamma_plus = 0.0}), 0.0);           // on the axis
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.gamma_plus = 0.5}), 0.1);           // above: held at the edge
  EXPECT_DOUBLE_EQ(raw->lift_coefficient({.gamma_plus = 0.05}), -0.4);
}

TEST(ExpressionLift, AShearReynoldsNumberFadesTheSameWay) {
  // Re_shear = gammadot d_p^2 / nu is proportional to the shear rate as gamma+ is: the same fade below its box.
  const fs::path p = fs::temp_directory_path() / "hs_learned_lift_reshear.toml";
  std::ofstream(p) << "name = \"cl\"\nkind = \"lift\"\noutput = \"C_l\"\nexpression = \"2*re_shear - 0.5\"\n"
                      "[variables]\nre_shear = \"Re_shear\"\n[validity]\nre_shear = [0.1, 0.3]\n";
  const auto clamped = hc::make_lift_closure({.model = "expression", .file = p});
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.re_shear = 0.2}), -0.1);
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.re_shear = 0.05}), -0.3 * 0.5);
  EXPECT_DOUBLE_EQ(clamped->lift_coefficient({.re_shear = 0.0}), 0.0);
}
