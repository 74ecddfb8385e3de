// SPDX-License-Identifier: MIT
// Insertion at a target hematocrit inside a periodic tube: count, no overlaps, inside, impossible targets.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/dem/insertion.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Tube;
using hs::common::Vec3;

struct TubeCase {
  double radius_m = 15e-6;
  double length_m = 60e-6;
  Tube tube{{.start_m = {0, 0, 0}, .end_m = {0, 0, length_m}, .radius_m = radius_m}};
  Domain domain{.box = {.lo = {-radius_m, -radius_m, 0}, .hi = {radius_m, radius_m, length_m}}, .periodic = {false, false, true}};
};

void expect_valid(const TubeCase& c, const InsertionResult& r, double radius) {
  for (const Vec3& x : r.positions_m) ASSERT_LE(c.tube.signed_distance(x), -radius * (1.0 - 1e-12));
  for (std::size_t i = 0; i < r.positions_m.size(); ++i) {
    for (std::size_t j = i + 1; j < r.positions_m.size(); ++j) {
      Vec3 d = r.positions_m[i] - r.positions_m[j];
      d.z -= c.length_m * std::round(d.z / c.length_m);   // periodic along the axis
      ASSERT_GE(norm(d), 2.0 * radius * (1.0 - 1e-12)) << i << " " << j;
    }
  }
}

TEST(Insertion, RandomSequentialAdditionHitsTheHematocrit) {
  const TubeCase c;
  const double r = 0.5 * default_particle_params().diameter_m;
  const double v_p = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  for (double ht : {0.05, 0.15, 0.25}) {
    const auto res = insert_at_volume_fraction(c.tube, c.domain, {.volume_fraction = ht, .radius_m = r, .seed = 11});
    EXPECT_FALSE(res.used_lattice) << ht;
    // The tube volume is exact (pi R^2 L); the count is round(ht V / V_p), so the fraction is within half a sphere.
    EXPECT_NEAR(res.region_volume_m3, std::numbers::pi * c.radius_m * c.radius_m * c.length_m, 1e-24);
    EXPECT_NEAR(res.achieved_fraction, ht, 0.5 * v_p / res.region_volume_m3);
    EXPECT_NEAR(static_cast<double>(res.positions_m.size()) * v_p / res.region_volume_m3, ht, 0.5 * v_p / res.region_volume_m3);
    expect_valid(c, res, r);
  }
}

TEST(Insertion, SameSeedSamePositions) {
  const TubeCase c;
  const double r = 0.5 * default_particle_params().diameter_m;
  const auto a = insert_at_volume_fraction(c.tube, c.domain, {.volume_fraction = 0.1, .radius_m = r, .seed = 5});
  const auto b = insert_at_volume_fraction(c.tube, c.domain, {.volume_fraction = 0.1, .radius_m = r, .seed = 5});
  ASSERT_EQ(a.positions_m.size(), b.positions_m.size());
  for (std::size_t i = 0; i < a.positions_m.size(); ++i) EXPECT_EQ(a.positions_m[i].x, b.positions_m[i].x);
}

TEST(Insertion, DenseTargetsFallBackToTheLattice) {
  const TubeCase c;
  const double r = 0.5 * default_particle_params().diameter_m;
  // Beyond the RSA jamming limit in a narrow tube (~0.3 here) but below the lattice capacity.
  const auto res = insert_at_volume_fraction(c.tube, c.domain, {.volume_fraction = 0.40, .radius_m = r, .seed = 2});
  EXPECT_TRUE(res.used_lattice);
  expect_valid(c, res, r);
}

TEST(Insertion, ImpossibleHematocritNamesValueAndMaximum) {
  const TubeCase c;
  const double r = 0.5 * default_particle_params().diameter_m;
  try {
    (void)insert_at_volume_fraction(c.tube, c.domain, {.volume_fraction = 0.7, .radius_m = r, .seed = 1});
    FAIL() << "no error";
  } catch (const hs::common::ConfigError& e) {
    const std::string m = e.what();
    std::cout << "measured: message: " << m << "\n";
    EXPECT_NE(m.find("hematocrit = 0.7"), std::string::npos) << m;
    EXPECT_NE(m.find("at most"), std::string::npos) << m;
    EXPECT_NE(m.find("hematocrit <= 0."), std::string::npos) << m;
  }
}

TEST(Insertion, GenericShapeVolumeBySampling) {
  // A tube given through the Shape interface only (a wrapper hides the Tube type): sampled volume within 0.5%.
  struct Hidden final : hs::common::Shape {
    const Tube& t;
    explicit Hidden(const Tube& tube) : t(tube) {}
    [[nodiscard]] double signed_distance(const Vec3& p) const override { return t.signed_distance(p); }
    [[nodiscard]] hs::common::Box3 bounds() const override { return t.bounds(); }
  };
  const TubeCase c;
  const Hidden h(c.tube);
  const double exact = std::numbers::pi * c.radius_m * c.radius_m * c.length_m;
  // 2e6 midpoint samples: the staircase error of a circle of ~100 samples across is ~1e-3.
  EXPECT_NEAR(region_volume_m3(h, c.domain) / exact, 1.0, 5e-3);
}

}  // namespace
}  // namespace hs::unresolved
