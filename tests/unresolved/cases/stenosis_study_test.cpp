// SPDX-License-Identifier: MIT
// The stenosis study's geometry: the committed unresolved throats are the resolved stenosis' profile ten times
// larger (one ConstrictionProfile, two sizes), the bins' fluid volumes against the closed-form tube volume, and the
// [study] keys' errors (ConfigError naming the key).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/geometry/shape_from_config.hpp"
#include "common/geometry/stenosed_tube.hpp"
#include "unresolved/cases/stenosis_study.hpp"

namespace hs::unresolved {
namespace {

const std::string kSource = HS_SOURCE_DIR;

/// The resolved stenosis' planar profile (height, throat height, constriction length: half-widths of the channel).
hs::common::ConstrictionProfile resolved_profile(const std::string& case_file) {
  auto file = hs::common::ConfigFile::load(kSource + "/cases/resolved/" + case_file);
  auto g = file->root().section("geometry");
  return {0.5 * g.positive("height_m"), 0.5 * g.positive("throat_height_m"), g.positive("constriction_length_m")};
}

std::shared_ptr<const hs::common::Shape> unresolved_shape(const std::string& throat) {
  auto file = hs::common::ConfigFile::load(kSource + "/cases/unresolved/stenosis/" + throat + "/case.toml");
  return hs::common::shape_from_config(file->root().section("geometry"));
}

TEST(StenosisStudy, CommittedThroatsAreTheResolvedProfileTenTimesLarger) {
  // The seed paper's section 4.4: section 3.2's channel "increased ten times in size". Equal to round-off (the case
  // files hold the numbers x10 as decimals).
  for (const auto& [resolved, throat] : {std::pair{"stenosis/case.toml", "throat-85um"},
                                         std::pair{"stenosis/throat-5.5um/case.toml", "throat-55um"},
                                         std::pair{"stenosis/throat-5.5um/case.toml", "throat-55um-fine"}}) {
    const auto big = resolved_profile(resolved).scaled(10.0);
    const auto shape = unresolved_shape(throat);
    const auto* tube = dynamic_cast<const hs::common::StenosedTube*>(shape.get());
    ASSERT_NE(tube, nullptr) << throat;
    const auto& p = tube->profile();
    EXPECT_NEAR(p.open_half_width_m / big.open_half_width_m, 1.0, 1e-12) << throat;
    EXPECT_NEAR(p.throat_half_width_m / big.throat_half_width_m, 1.0, 1e-12) << throat;
    EXPECT_NEAR(p.length_m / big.length_m, 1.0, 1e-12) << throat;
    for (double s = -120e-6; s <= 120e-6; s += 7e-6) EXPECT_NEAR(p.half_width(s), big.half_width(s), 1e-15) << throat;
  }
}

std::string case_text(const std::string& study) {
  return "[geometry]\nshape = \"stenosed-tube\"\nradius_m = 75e-6\nthroat_radius_m = 27.5e-6\nconstriction_length_m = 200e-6\n"
         "constriction_centre_m = 250e-6\nlength_m = 650e-6\n" + study;
}

std::optional<StenosisStudySpec> parse(const std::string& text) {
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  const auto shape = hs::common::shape_from_config(file->root().section("geometry"));
  return parse_stenosis_study(file->root(), *shape);
}

const char* kStudy = "[study]\nx_bins = 65\nupstream_window_m = [30e-6, 100e-6]\ndownstream_window_m = [350e-6, 450e-6]\n";

TEST(StenosisStudy, BinsAndTheirFluidVolume) {
  const auto s = parse(case_text(kStudy));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->bin_width_m(), 10e-6, 1e-18);
  EXPECT_EQ(s->bin_of(0.0), 0);
  EXPECT_EQ(s->bin_of(15e-6), 1);
  EXPECT_EQ(s->bin_of(650e-6), 64);   // the outlet face falls in the last bin
  EXPECT_EQ(s->bin_of(-1e-9), -1);
  EXPECT_NEAR(s->throat_x_m(), 250e-6, 1e-18);
  EXPECT_NEAR(s->radius_at(250e-6), 27.5e-6, 1e-18);
  EXPECT_NEAR(s->radius_at(100e-6), 75e-6, 1e-18);
  // Closed form: with a = R - r_t, h = R - a (1 + cos k s) / 2 over the constriction L_c integrates to
  // pi L_c (R^2 - R a + 3 a^2 / 8); the straight parts are pi R^2 each. Simpson's rule on 64 panels a bin is exact to
  // ~1e-10 here (the cosine spans 20 bins); 1e-9 of the volume leaves room for the sum's round-off.
  const double r = 75e-6;
  const double a = r - 27.5e-6;
  const double exact = std::numbers::pi * r * r * 450e-6 + std::numbers::pi * 200e-6 * (r * r - r * a + 3.0 * a * a / 8.0);
  double sum = 0.0;
  for (const double v : s->bin_fluid_m3()) sum += v;
  EXPECT_NEAR(sum / exact, 1.0, 1e-9);
  EXPECT_NEAR(s->bin_fluid_m3()[0], std::numbers::pi * r * r * 10e-6, 1e-12 * exact);
}

TEST(StenosisStudy, BadKeysNameThemselves) {
  const auto fails_on = [](const std::string& text, const std::string& key) {
    try {
      (void)parse(text);
    } catch (const hs::common::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "no ConfigError for " << key;
  };
  fails_on(case_text("[study]\nx_bins = 65\nupstream_window_m = [100e-6, 30e-6]\ndownstream_window_m = [350e-6, 450e-6]\n"),
           "upstream_window_m");
  fails_on(case_text("[study]\nx_bins = 65\nupstream_window_m = [30e-6, 100e-6]\ndownstream_window_m = [350e-6, 700e-6]\n"),
           "downstream_window_m");
  fails_on(case_text("[study]\nx_bins = 1\nupstream_window_m = [30e-6, 100e-6]\ndownstream_window_m = [350e-6, 450e-6]\n"),
           "x_bins");
  fails_on("[geometry]\nshape = \"tube\"\nradius_m = 75e-6\nlength_m = 650e-6\n" + std::string(kStudy), "x_bins");
  EXPECT_FALSE(parse(case_text("")));   // no [study]: no study measurement
}

}  // namespace
}  // namespace hs::unresolved
