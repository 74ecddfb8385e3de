// SPDX-License-Identifier: MIT
// DI and principal axes of point clouds whose answer is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "resolved/measure/cell_shape.hpp"

using hs::common::Vec3;
using hs::resolved::measure_cell_shape;

namespace {
/// Points on an ellipsoid with semi-axes (a, b, c), rotated by `angle` about z, shifted by `shift`.
std::vector<Vec3> ellipsoid(double a, double b, double c, double angle, Vec3 shift) {
  std::vector<Vec3> pts;
  const int n = 40;
  for (int i = 0; i <= n; ++i) {
    const double theta = std::numbers::pi * i / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = std::numbers::pi * j / n;
      const Vec3 p{a * std::sin(theta) * std::cos(phi), b * std::sin(theta) * std::sin(phi), c * std::cos(theta)};
      pts.push_back(Vec3{p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle), p.z} + shift);
    }
  }
  return pts;
}
}  // namespace

TEST(CellShape, EllipsoidAxesAndDeformationIndex) {
  const auto s = measure_cell_shape(ellipsoid(4.0, 2.0, 1.0, 0.3, {10, -5, 2}));
  // Extents are 2a, 2b, 2c exactly: the sampled points include the axis tips (theta = pi/2, phi = 0 etc.).
  EXPECT_NEAR(s.extents_m[0], 8.0, 1e-9);
  EXPECT_NEAR(s.extents_m[1], 4.0, 1e-9);
  EXPECT_NEAR(s.extents_m[2], 2.0, 1e-9);
  EXPECT_NEAR(s.deformation_index(), (8.0 - 2.0) / (8.0 + 2.0), 1e-9);
  EXPECT_NEAR(s.centroid_m.x, 10.0, 1e-9);
  EXPECT_NEAR(hs::resolved::inclination_angle(s, {1, 0, 0}, {0, 1, 0}), 0.3, 1e-9);
}

TEST(CellShape, SphereHasZeroDeformation) {
  const auto s = measure_cell_shape(ellipsoid(3.0, 3.0, 3.0, 0.0, {}));
  EXPECT_NEAR(s.deformation_index(), 0.0, 1e-3);   // sampled sphere: extents equal to the sampling's resolution
  EXPECT_NEAR(s.projected_m[2], 6.0, 1e-12);
}

TEST(CellShape, GyrationRadiiOfABoxsCorners) {
  // The 8 corners (+-a, +-b, +-c) of a box, rotated and shifted: each coordinate's mean square is a^2, b^2, c^2,
  // so the gyration radii are a, b, c and the gyration DI (a - c) / (a + c), to round-off.
  std::vector<Vec3> corners;
  for (const double x : {-4.0, 4.0})
    for (const double y : {-2.0, 2.0})
      for (const double z : {-1.0, 1.0}) {
        const double t = 0.4;
        const Vec3 turned{x * std::cos(t) - y * std::sin(t), x * std::sin(t) + y * std::cos(t), z};
        corners.push_back(turned + Vec3{3, 1, -2});
      }
  const auto s = measure_cell_shape(corners);
  EXPECT_NEAR(s.gyration_radii_m[0], 4.0, 1e-12);
  EXPECT_NEAR(s.gyration_radii_m[1], 2.0, 1e-12);
  EXPECT_NEAR(s.gyration_radii_m[2], 1.0, 1e-12);
  EXPECT_NEAR(s.gyration_deformation_index(), 3.0 / 5.0, 1e-12);
}
