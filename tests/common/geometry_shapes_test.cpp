// SPDX-License-Identifier: MIT
// Signed distances and inside/outside of the shared shapes, against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "common/geometry/bifurcation.hpp"
#include "common/geometry/box_shape.hpp"
#include "common/geometry/shape_operations.hpp"
#include "common/geometry/stenosed_channel.hpp"
#include "common/geometry/stenosed_tube.hpp"
#include "common/geometry/tube.hpp"

using namespace hs::common;

TEST(BoxShape, ExactDistanceInsideAndOutside) {
  const BoxShape b({{0, 0, 0}, {2, 4, 6}});
  EXPECT_DOUBLE_EQ(b.signed_distance({1, 2, 3}), -1.0);      // nearest face x = 0 or 2
  EXPECT_DOUBLE_EQ(b.signed_distance({3, 2, 3}), 1.0);
  EXPECT_DOUBLE_EQ(b.signed_distance({3, 5, 3}), std::sqrt(2.0));   // edge region
}

TEST(StenosedTube, ThroatAndOpenSections) {
  const StenosedTube t({.start_m = {0, 0, 0}, .end_m = {100, 0, 0}, .radius_m = 10, .throat_radius_m = 4,
                        .constriction_length_m = 20, .constriction_centre_m = 50});
  EXPECT_NEAR(t.signed_distance({50, 0, 0}), -4.0, 1e-12);    // throat: radius 4
  EXPECT_NEAR(t.signed_distance({50, 4, 0}), 0.0, 1e-12);
  EXPECT_NEAR(t.signed_distance({10, 0, 3}), -7.0, 1e-12);    // open part: radius 10
  EXPECT_GT(t.signed_distance({50, 5, 0}), 0.0);              // inside the open radius but in the plaque
  EXPECT_NEAR(t.signed_distance({45, 7, 0}), 0.0, 1e-12);     // mid-slope: r(45) = 10 - 3(1 + cos(-pi/2)) = 7
}

TEST(StenosedChannel, HeightsOfThePaper) {
  // Seed paper 3.2: a 15 um channel narrowed to 5.5 um.
  const StenosedChannel c({.x_start_m = 0, .x_end_m = 60e-6, .centre_y_m = 0, .height_m = 15e-6, .throat_height_m = 5.5e-6,
                           .constriction_length_m = 10e-6, .constriction_centre_x_m = 30e-6, .z_lo_m = -10e-6, .z_hi_m = 10e-6});
  EXPECT_NEAR(c.signed_distance({30e-6, 0, 0}), -2.75e-6, 1e-18);
  EXPECT_NEAR(c.signed_distance({5e-6, 7.5e-6, 1e-6}), 0.0, 1e-18);
  EXPECT_TRUE(c.inside({5e-6, 7e-6, 0}));
  EXPECT_FALSE(c.inside({30e-6, 3e-6, 0}));
}

TEST(Bifurcation, BranchesAreFluidAndOutsideIsWall) {
  const Bifurcation b({.junction_m = {100, 0, 0}, .parent_radius_m = 10, .parent_length_m = 100,
                       .daughter_radius_m = {8, 6}, .daughter_length_m = {100, 100}, .daughter_angle_deg = {30, -30}});
  EXPECT_NEAR(b.signed_distance({50, 0, 0}), -10.0, 1e-12);   // parent axis
  const double a = 30.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(b.signed_distance({100 + 50 * std::cos(a), 50 * std::sin(a), 0}), -8.0, 1e-12);    // daughter 0 axis
  EXPECT_NEAR(b.signed_distance({100 + 50 * std::cos(a), -50 * std::sin(a), 0}), -6.0, 1e-12);   // daughter 1 axis
  EXPECT_TRUE(b.inside({100, 0, 0}));                          // the junction
  EXPECT_GT(b.signed_distance({50, 15, 0}), 0.0);              // beside the parent
  EXPECT_GT(b.signed_distance({160, 0, 0}), 0.0);              // between the daughters, downstream
  EXPECT_NEAR(b.bounds().lo.x, -10.0, 1e-12);
}

TEST(ShapeOperations, UnionDifferenceAndTransform) {
  auto left = std::make_shared<BoxShape>(Box3{{0, 0, 0}, {1, 1, 1}});
  auto right = std::make_shared<BoxShape>(Box3{{1, 0, 0}, {2, 1, 1}});
  const ShapeUnion u({left, right});
  EXPECT_TRUE(u.inside({1.5, 0.5, 0.5}));
  EXPECT_TRUE(u.inside({0.5, 0.5, 0.5}));
  EXPECT_DOUBLE_EQ(u.bounds().hi.x, 2.0);
  const ShapeDifference d(left, std::make_shared<BoxShape>(Box3{{0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}}));
  EXPECT_FALSE(d.inside({0.5, 0.5, 0.5}));
  EXPECT_TRUE(d.inside({0.2, 0.2, 0.2}));
  // A tube along x rotated by 90 degrees about z runs along y.
  auto tube = std::make_shared<Tube>(TubeSpec{.start_m = {0, 0, 0}, .end_m = {10, 0, 0}, .radius_m = 1});
  const auto rotated = TransformedShape::rotate_translate(tube, {0, 0, 1}, std::numbers::pi / 2, {5, 0, 0});
  EXPECT_NEAR(rotated.signed_distance({5, 3, 0}), -1.0, 1e-12);
  EXPECT_NEAR(rotated.signed_distance({7, 3, 0}), 1.0, 1e-12);
  EXPECT_NEAR(rotated.bounds().hi.y, 10.0, 1e-12);
}
