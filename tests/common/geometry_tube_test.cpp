// SPDX-License-Identifier: MIT
// The tube shape: signed distance and wall crossing along a lattice link.
#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry/tube.hpp"

using hs::common::Tube;
using hs::common::Vec3;

TEST(Tube, SignedDistanceIsRadial) {
  const Tube t({.start_m = {0, 0, 0}, .end_m = {0, 0, 50e-6}, .radius_m = 25e-6});
  EXPECT_NEAR(t.signed_distance({0, 0, 10e-6}), -25e-6, 1e-18);
  EXPECT_NEAR(t.signed_distance({30e-6, 0, 10e-6}), 5e-6, 1e-18);
  EXPECT_TRUE(t.inside({10e-6, 10e-6, 0}));
  EXPECT_NEAR(t.bounds().hi.x, 25e-6, 1e-18);
}

TEST(Tube, WallCrossingFractionIsExact) {
  const Tube t({.start_m = {0, 0, 0}, .end_m = {0, 0, 1}, .radius_m = 1.0});
  // From x = 0.5 to x = 1.5 the wall is crossed at x = 1: q = 0.5.
  EXPECT_NEAR(hs::common::wall_crossing_fraction(t, {0.5, 0, 0}, {1.5, 0, 0}), 0.5, 1e-12);
  // Diagonal link from (0.6, 0.6) to (0.8, 0.8): |p| = 1 at s = 1/sqrt(2) -> q = (0.70711 - 0.6)/0.2.
  const double q = (1.0 / std::sqrt(2.0) - 0.6) / 0.2;
  EXPECT_NEAR(hs::common::wall_crossing_fraction(t, {0.6, 0.6, 0}, {0.8, 0.8, 0}), q, 1e-11);
}
