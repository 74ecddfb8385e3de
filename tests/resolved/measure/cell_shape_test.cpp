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

TEST(CellShape, DiscNormalAgainstTheVorticity) {
  // The shortest axis of a (4, 2, 1) ellipsoid turned about z is z: 0 against a vorticity along z (a rolling disc),
  // pi/2 against any direction in the x-y plane (a disc turning in that plane), and the tilt in between; the sign of
  // the vorticity does not matter (an axis has none).
  const auto s = measure_cell_shape(ellipsoid(4.0, 2.0, 1.0, 0.7, {1, 2, 3}));
  using hs::resolved::normal_to_vorticity_angle;
  EXPECT_NEAR(normal_to_vorticity_angle(s, {0, 0, 2}), 0.0, 1e-6);   // acos near 1 amplifies round-off to ~1e-8
  EXPECT_NEAR(normal_to_vorticity_angle(s, {0, 0, -1}), 0.0, 1e-6);
  EXPECT_NEAR(normal_to_vorticity_angle(s, {1, 1, 0}), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(normal_to_vorticity_angle(s, {0, std::sin(0.5), std::cos(0.5)}), 0.5, 1e-9);
}
