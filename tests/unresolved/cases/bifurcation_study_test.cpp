// SPDX-License-Identifier: MIT
// The bifurcation study's geometry: the disc's strips (closed form), which branch a point is in, where a point lies
// across a cut, and the [study] keys' errors (ConfigError naming the key).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/geometry/shape_from_config.hpp"
#include "unresolved/cases/bifurcation_study.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

std::string case_text(const std::string& study) {
  return "[geometry]\nshape = \"bifurcation\"\nparent_diameter_m = 30e-6\nparent_length_m = 90e-6\n"
         "daughter_diameters_m = [30e-6, 30e-6]\ndaughter_lengths_m = [150e-6, 160e-6]\ndaughter_angles_deg = [0.0, 90.0]\n" + study;
}

const char* kStudy = "[study]\nbranch_names = [\"outlet\", \"daughter\"]\ncut_distance_m = 60e-6\ncut_thickness_m = 6e-6\n"
                     "profile_bins = 10\ndi_range = [0.4, 0.6]\ndi_bins = 40\ndi_threshold = 0.505\n";

std::optional<BifurcationStudySpec> parse(const std::string& study) {
  auto file = hs::common::ConfigFile::parse(case_text(study), "case.toml");
  const auto shape = hs::common::shape_from_config(file->root().section("geometry"));
  return parse_bifurcation_study(file->root(), *shape);
}

TEST(BifurcationStudy, DiscStripsSumToOneAndMatchTheHalfDisc) {
  const auto f = disc_strip_fractions(10);
  double sum = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    sum += f[i];
    EXPECT_NEAR(f[i], f[f.size() - 1 - i], 1e-15);   // symmetric
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  // Two strips: the half discs. The outer tenth of the diameter: (acos(0.8) - 0.8 * 0.6) / pi = 0.05204.
  EXPECT_NEAR(disc_strip_fractions(2)[0], 0.5, 1e-15);
  EXPECT_NEAR(f[0], (std::acos(0.8) - 0.8 * 0.6) / std::numbers::pi, 1e-14);
}

TEST(BifurcationStudy, BranchesAndCuts) {
  const auto s = parse(kStudy);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->branches[1].name, "outlet");
  const Vec3 j = s->junction_m;   // (90 um, 0, 0)
  EXPECT_EQ(s->branch_of(j + Vec3{-50e-6, 3e-6, 0.0}), 0);   // parent
  EXPECT_EQ(s->branch_of(j + Vec3{50e-6, 3e-6, 0.0}), 1);    // outlet (+x)
  EXPECT_EQ(s->branch_of(j + Vec3{3e-6, 50e-6, 0.0}), 2);    // daughter (+y)
  // Outlet: across = z x (+x) = +y; w = (y + R) / 2R inside the slab 57..63 um past the junction.
  const auto w = s->cut_coordinate(1, j + Vec3{60e-6, 7.5e-6, 1e-6});
  ASSERT_TRUE(w);
  EXPECT_NEAR(*w, 0.75, 1e-12);
  EXPECT_FALSE(s->cut_coordinate(1, j + Vec3{63.5e-6, 0.0, 0.0}));
  // Daughter: across = z x (+y) = -x, so w grows towards the upstream (-x) wall.
  const auto up = s->cut_coordinate(2, j + Vec3{-12e-6, 60e-6, 0.0});
  const auto down = s->cut_coordinate(2, j + Vec3{12e-6, 61e-6, 0.0});
  ASSERT_TRUE(up && down);
  EXPECT_NEAR(*up, 0.9, 1e-12);
  EXPECT_NEAR(*down, 0.1, 1e-12);
  EXPECT_FALSE(s->cut_coordinate(2, j + Vec3{-15.1e-6, 60e-6, 0.0}));   // beyond the radius
  const auto v = s->cut_bin_fluid_m3(2);
  double total = 0.0;
  for (const double x : v) total += x;
  EXPECT_NEAR(total, std::numbers::pi * 15e-6 * 15e-6 * 6e-6, 1e-28);
}

TEST(BifurcationStudy, KeysAreChecked) {
  EXPECT_FALSE(parse(""));   // no [study]: plain open-geometry
  const auto fails = [](const std::string& study, const std::string& key) {
    try {
      (void)parse(study);
    } catch (const hs::common::ConfigError& e) {
      return std::string(e.what()).find(key) != std::string::npos;
    }
    return false;
  };
  std::string s = kStudy;
  EXPECT_TRUE(fails(s.replace(s.find("60e-6"), 5, "16e-6"), "cut_distance_m"));   // the slab reaches the junction ball
  s = kStudy;
  EXPECT_TRUE(fails(s.replace(s.find("\"outlet\""), 8, "\"parent\""), "branch_names"));
  s = kStudy;
  EXPECT_TRUE(fails(s.replace(s.find("0.505"), 5, "0.7"), "di_threshold"));   // outside di_range
}

}  // namespace
}  // namespace hs::unresolved
