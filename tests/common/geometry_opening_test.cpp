// SPDX-License-Identifier: MIT
// Named openings: which discs cut the domain where the fluid is, and the messages for those that do not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/geometry/bifurcation.hpp"
#include "common/geometry/opening.hpp"
#include "common/geometry/openings_from_config.hpp"
#include "common/geometry/tube.hpp"

using namespace hs::common;

namespace {

constexpr double radius = 10e-6;
constexpr double length = 100e-6;

Tube tube() { return Tube({.start_m = {0, 0, 0}, .end_m = {length, 0, 0}, .radius_m = radius}); }

Opening inlet() {
  return {.name = "in", .kind = OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {-1, 0, 0}, .radius_m = radius};
}

std::string problem_key(const Opening& o, const Shape& s, const Box3& box) {
  const auto p = find_opening_problem(o, s, box);
  return p ? p->key : std::string("none");
}

}  // namespace

TEST(Opening, TubeEndsAreValidOpenings) {
  const Tube t = tube();
  const Opening out{.name = "out", .kind = OpeningKind::outlet, .centre_m = {length, 0, 0}, .normal = {1, 0, 0},
                    .radius_m = radius};
  EXPECT_FALSE(find_opening_problem(inlet(), t, t.bounds()).has_value());
  EXPECT_FALSE(find_opening_problem(out, t, t.bounds()).has_value());
  EXPECT_NO_THROW(check_openings({inlet(), out}, t, t.bounds()));
  EXPECT_NEAR(inlet().area_m2(), std::numbers::pi * radius * radius, 1e-24);
  EXPECT_NEAR(out.height_m({length + 1e-6, 3e-6, 0}), 1e-6, 1e-18);
  EXPECT_NEAR(out.lateral_m({length + 1e-6, 3e-6, 4e-6}), 5e-6, 1e-18);
}

TEST(Opening, EachWayOfMissingTheWallIsNamed) {
  const Tube t = tube();
  Opening mid = inlet();
  mid.centre_m = {0.5 * length, 0, 0};   // inside the fluid but not on the domain boundary
  EXPECT_EQ(problem_key(mid, t, t.bounds()), "centre_m");

  const Box3 wide{{0, -3 * radius, -3 * radius}, {length, 3 * radius, 3 * radius}};
  Opening beside = inlet();
  beside.centre_m = {0, 2 * radius, 0};   // on the inlet face, but in the wall material beside the tube
  beside.radius_m = 0.5 * radius;
  const auto p = find_opening_problem(beside, t, wide);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->key, "centre_m");
  EXPECT_NE(p->what.find("does not cut the geometry's wall"), std::string::npos) << p->what;

  Opening inward = inlet();
  inward.normal = {1, 0, 0};   // points into the fluid
  EXPECT_EQ(problem_key(inward, t, t.bounds()), "normal");
  Opening slanted = inlet();
  slanted.normal = normalized(Vec3{-1, 1, 0});   // a Cartesian grid cuts the tube only along its faces
  EXPECT_EQ(problem_key(slanted, t, t.bounds()), "normal");
  Opening unnormalised = inlet();
  unnormalised.normal = {-2, 0, 0};
  EXPECT_EQ(problem_key(unnormalised, t, t.bounds()), "normal");
  Opening unnamed = inlet();
  unnamed.name.clear();
  EXPECT_EQ(problem_key(unnamed, t, t.bounds()), "name");
}

TEST(Opening, ADiscWiderThanTheTubeIsRejectedWithTheLargestThatFits) {
  const Tube t = tube();
  const Box3 wide{{0, -3 * radius, -3 * radius}, {length, 3 * radius, 3 * radius}};
  Opening big = inlet();
  big.radius_m = 1.2 * radius;
  const auto p = find_opening_problem(big, t, wide);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->key, "radius_m");
  EXPECT_NE(p->what.find("into the wall"), std::string::npos) << p->what;
  // Bisection to 1e-9 of the reach (the box diagonal, ~1.1e-4 m): the tube radius to ~1e-13 m.
  EXPECT_NEAR(largest_inscribed_radius_m(big, t, wide), radius, 1e-12);
  Opening smaller = inlet();
  smaller.radius_m = 0.5 * radius;   // a patch smaller than the section is allowed
  EXPECT_FALSE(find_opening_problem(smaller, t, wide).has_value());
}

TEST(Opening, TwoBranchesLeavingThroughOneFaceGetOneOutletEach) {
  const double xj = 100e-6, r = 8e-6, a = 30.0 * std::numbers::pi / 180.0;
  const Bifurcation b({.junction_m = {xj, 0, 0}, .parent_radius_m = 10e-6, .parent_length_m = xj,
                       .daughter_radius_m = {r, r}, .daughter_length_m = {200e-6, 200e-6},
                       .daughter_angle_deg = {30, -30}});
  const double x_out = xj + 100e-6, y_out = 100e-6 * std::tan(a);
  const Box3 box{{0, -150e-6, -20e-6}, {x_out, 150e-6, 20e-6}};
  // The plane x = x_out cuts each daughter in an ellipse of semi-axes r / cos(a) and r: the inscribed disc is r.
  const Opening up{.name = "up", .kind = OpeningKind::outlet, .centre_m = {x_out, y_out, 0}, .normal = {1, 0, 0},
                   .radius_m = r};
  Opening down = up;
  down.name = "down";
  down.centre_m.y = -y_out;
  const Opening in{.name = "in", .kind = OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {-1, 0, 0},
                   .radius_m = 10e-6};
  EXPECT_NO_THROW(check_openings({in, up, down}, b, box));
  EXPECT_NEAR(largest_inscribed_radius_m(up, b, box), r, 1e-12);

  Opening twin = up;   // same name again
  EXPECT_THROW(check_openings({in, up, twin}, b, box), ConfigError);
  Opening overlapping = up;
  overlapping.name = "overlap";
  overlapping.radius_m = 0.5 * r;
  const auto p = find_openings_problem({in, up, overlapping}, b, box);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->index, 2u);
  EXPECT_EQ(p->problem.key, "radius_m");
}

TEST(Opening, TangentBasisIsOrthonormal) {
  for (const Vec3 n : {Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}, normalized(Vec3{1, 2, 3})}) {
    const auto [t1, t2] = tangent_basis(n);
    EXPECT_NEAR(dot(t1, n), 0.0, 1e-15);
    EXPECT_NEAR(dot(t2, n), 0.0, 1e-15);
    EXPECT_NEAR(dot(t1, t2), 0.0, 1e-15);
    EXPECT_NEAR(norm(t1), 1.0, 1e-15);
    EXPECT_NEAR(dot(cross(t1, t2), n), 1.0, 1e-15);
  }
}

TEST(OpeningsFromConfig, ReadsNormalisesAndNamesTheBadKey) {
  const Tube t = tube();
  const auto file = ConfigFile::parse(R"(
[openings.in]
kind = "inlet"
centre_m = [0, 0, 0]
normal = [-2, 0, 0]
radius_m = 10e-6
[openings.out]
kind = "outlet"
centre_m = [100e-6, 0, 0]
normal = [1, 0, 0]
radius_m = 10e-6
)", "case.toml");
  const auto openings = openings_from_config(file->root().section("openings"), t, t.bounds());
  ASSERT_EQ(openings.size(), 2u);
  EXPECT_EQ(openings[0].name, "in");
  EXPECT_EQ(openings[0].kind, OpeningKind::inlet);
  EXPECT_DOUBLE_EQ(openings[0].normal.x, -1.0);
  EXPECT_EQ(openings[1].kind, OpeningKind::outlet);
  EXPECT_NO_THROW(file->finish());

  const auto bad = ConfigFile::parse(R"(
[openings.out]
kind = "outlet"
centre_m = [50e-6, 0, 0]
normal = [1, 0, 0]
radius_m = 10e-6
)", "case.toml");
  try {
    (void)openings_from_config(bad->root().section("openings"), t, t.bounds());
    FAIL() << "an opening in the middle of the tube was accepted";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("case.toml: [openings.out] centre_m = [ 5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("face of the domain box"), std::string::npos) << msg;
  }
  const auto bad_kind = ConfigFile::parse("[openings.x]\nkind = \"wall\"\n", "case.toml");
  EXPECT_THROW((void)openings_from_config(bad_kind->root().section("openings"), t, t.bounds()), ConfigError);
}
