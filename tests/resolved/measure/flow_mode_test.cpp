// SPDX-License-Identifier: MIT
// Flow-mode classification on synthetic motions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "resolved/measure/flow_mode.hpp"

using namespace hs::resolved;

namespace {
double fold_axis(double a) {   // into (-pi/2, pi/2]
  while (a > std::numbers::pi / 2) a -= std::numbers::pi;
  while (a <= -std::numbers::pi / 2) a += std::numbers::pi;
  return a;
}
double fold_phase(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

TEST(FlowMode, TumblingTankTreadingSteady) {
  std::vector<double> incl_tumble, incl_tt, phase_rot, phase_still, incl_still;
  for (int i = 0; i < 400; ++i) {
    const double t = 0.01 * i;
    incl_tumble.push_back(fold_axis(-1.5 * t));         // long axis turns 6 rad
    phase_rot.push_back(fold_phase(-2.0 * t));           // marker turns 8 rad
    incl_tt.push_back(0.2 + 0.05 * std::sin(3 * t));     // small swinging about 0.2 rad
    incl_still.push_back(0.0);
    phase_still.push_back(0.1);
  }
  EXPECT_EQ(classify_flow_mode(incl_tumble, phase_rot), FlowMode::tumbling);
  EXPECT_EQ(classify_flow_mode(incl_tt, phase_rot), FlowMode::tank_treading);
  EXPECT_EQ(classify_flow_mode(incl_still, phase_still), FlowMode::steady);
  EXPECT_EQ(to_string(FlowMode::tank_treading), "tank-treading");
}

TEST(DiscOrientation, MeanAngleToTheVorticityInThirdsOfAQuarterCircle) {
  using hs::resolved::classify_disc_orientation;
  const double deg = std::numbers::pi / 180.0;
  EXPECT_EQ(classify_disc_orientation(20 * deg), "rolling");
  EXPECT_EQ(classify_disc_orientation(78 * deg), "in-shear-plane");
  EXPECT_EQ(classify_disc_orientation(45 * deg), "oblique");
  EXPECT_EQ(classify_disc_orientation(29.9 * deg), "rolling");
  EXPECT_EQ(classify_disc_orientation(60.1 * deg), "in-shear-plane");
  EXPECT_EQ(classify_disc_orientation(std::nan("")), "");   // nothing sampled
}
