// SPDX-License-Identifier: MIT
// The membrane-wall repulsion of the stenosis case: linear contact spring along the wall normal, zero beyond its range,
// and positions wrapped into the periodic box before the shape is asked.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/geometry/stenosed_channel.hpp"
#include "resolved/cases/wall_repulsion.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

// Channel 15 um high (walls y = 0 and 15 um away from the constriction at x = 25 +- 10 um), box 60 um long.
const common::StenosedChannel kChannel(common::StenosedChannelSpec{
    .x_start_m = 0.0, .x_end_m = 60e-6, .centre_y_m = 7.5e-6, .height_m = 15e-6, .throat_height_m = 5.5e-6,
    .constriction_length_m = 20e-6, .constriction_centre_x_m = 25e-6, .z_lo_m = 0.0, .z_hi_m = 16e-6});

TEST(WallRepulsion, LinearSpringAlongTheNormalWithinTheRange) {
  WallRepulsion rep(kChannel, {.range_m = 0.5e-6, .stiffness_N_m = 2e-5, .period_x_m = 60e-6});
  // 0.2 um below the top wall, 0.1 um inside the bottom wall, 1 um from the top wall (out of range).
  const std::vector<Vec3> x{{50e-6, 14.8e-6, 1e-6}, {5e-6, -0.1e-6, 1e-6}, {50e-6, 14e-6, 1e-6}};
  std::vector<Vec3> f(3);
  rep.add_forces(x, f);
  // Straight walls: the distance is exact and the normal is -y (top) and +y (bottom); 1e-12 of the force for the
  // central-difference normal of a linear distance (exact up to round-off).
  EXPECT_NEAR(f[0].y, -2e-5 * 0.3e-6, 1e-12 * 2e-5 * 0.3e-6 + 1e-24);
  EXPECT_NEAR(f[0].x, 0.0, 1e-20);
  EXPECT_NEAR(f[1].y, 2e-5 * 0.6e-6, 1e-9 * 2e-5 * 0.6e-6);
  EXPECT_EQ(f[2].y, 0.0);
  EXPECT_EQ(rep.last_vertices(), 2);
  EXPECT_NEAR(rep.last_total_N(), 2e-5 * 0.9e-6, 1e-9 * 2e-5 * 0.9e-6);
}

TEST(WallRepulsion, WrapsPositionsIntoThePeriodicBox) {
  WallRepulsion rep(kChannel, {.range_m = 0.5e-6, .stiffness_N_m = 2e-5, .period_x_m = 60e-6});
  // x = 85 um is the throat (25 um) one period on: the throat wall is at y = 7.5 + 2.75 um; 0.2 um below it.
  std::vector<Vec3> f(1);
  rep.add_forces(std::vector<Vec3>{{85e-6, 10.05e-6, 0.0}}, f);
  EXPECT_NEAR(f[0].y, -2e-5 * 0.3e-6, 1e-6 * 2e-5 * 0.3e-6);   // slope 0 at the throat: normal -y
}

TEST(WallRepulsion, ZeroRangeSwitchesItOff) {
  WallRepulsion rep(kChannel, {.range_m = 0.0, .stiffness_N_m = 2e-5, .period_x_m = 60e-6});
  std::vector<Vec3> f(1);
  rep.add_forces(std::vector<Vec3>{{50e-6, -1e-6, 0.0}}, f);
  EXPECT_EQ(f[0].y, 0.0);
  EXPECT_FALSE(rep.enabled());
}

}  // namespace
}  // namespace hs::resolved
