// SPDX-License-Identifier: MIT
// Flow conditions of named openings: the case-file keys (flow_rate_m3_s, pressure_Pa, flow_fraction) and the
// ConfigErrors (exit 2 in app/main.cpp) for missing, contradictory or inconsistent ones.
#include <gtest/gtest.h>

#include <string>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/geometry/opening_condition.hpp"
#include "common/geometry/openings_from_config.hpp"
#include "common/geometry/tube.hpp"

using namespace hs::common;

namespace {

constexpr double radius = 10e-6;
constexpr double length = 100e-6;

Tube tube() { return Tube({.start_m = {0, 0, 0}, .end_m = {length, 0, 0}, .radius_m = radius}); }

/// A tube with an inlet at x = 0 and an outlet at x = L; `in_keys` and `out_keys` are the sections' extra lines.
std::string tube_case(const std::string& in_keys, const std::string& out_keys) {
  return "[openings.in]\nkind = \"inlet\"\ncentre_m = [0, 0, 0]\nnormal = [-1, 0, 0]\nradius_m = 10e-6\n" + in_keys +
         "\n[openings.out]\nkind = \"outlet\"\ncentre_m = [100e-6, 0, 0]\nnormal = [1, 0, 0]\nradius_m = 10e-6\n" +
         out_keys + "\n";
}

/// The ConfigError message of reading `text`, or "" when it reads.
std::string error_of(const std::string& text) {
  const Tube t = tube();
  const auto file = ConfigFile::parse(text, "case.toml");
  try {
    (void)opening_conditions_from_config(file->root().section("openings"), t, t.bounds());
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; }

}  // namespace

TEST(OpeningConditions, ReadsEachConditionKey) {
  const Tube t = tube();
  const auto file = ConfigFile::parse(tube_case("flow_rate_m3_s = 3.1e-13", "pressure_Pa = -12.5"), "case.toml");
  const auto c = opening_conditions_from_config(file->root().section("openings"), t, t.bounds());
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].opening.name, "in");
  EXPECT_EQ(c[0].type, OpeningFlowType::flow_rate_inlet);
  EXPECT_DOUBLE_EQ(c[0].flow_rate_m3_s, 3.1e-13);
  EXPECT_EQ(c[1].type, OpeningFlowType::pressure_outlet);
  EXPECT_DOUBLE_EQ(c[1].pressure_Pa, -12.5);
  EXPECT_NO_THROW(file->finish());   // every key was read

  const auto split = ConfigFile::parse(tube_case("flow_rate_m3_s = 1e-13", "flow_fraction = 1"), "case.toml");
  const auto s = opening_conditions_from_config(split->root().section("openings"), t, t.bounds());
  EXPECT_EQ(s[1].type, OpeningFlowType::flow_fraction_outlet);
  EXPECT_DOUBLE_EQ(s[1].flow_fraction, 1.0);
}

TEST(OpeningConditions, AnOutletWithNeitherPressureNorFlowIsAnError) {
  const std::string msg = error_of(tube_case("flow_rate_m3_s = 1e-13", ""));
  EXPECT_TRUE(has(msg, "case.toml: [openings.out] pressure_Pa: missing")) << msg;
  EXPECT_TRUE(has(msg, "flow_fraction")) << msg;   // the message names both ways out
}

TEST(OpeningConditions, ContradictoryOrMisplacedKeysAreErrors) {
  std::string msg = error_of(tube_case("flow_rate_m3_s = 1e-13", "pressure_Pa = 0\nflow_fraction = 0.5"));
  EXPECT_TRUE(has(msg, "[openings.out] flow_fraction = 0.5: is redundant with pressure_Pa")) << msg;
  msg = error_of(tube_case("flow_rate_m3_s = 1e-13\npressure_Pa = 5", "pressure_Pa = 0"));
  EXPECT_TRUE(has(msg, "[openings.in] pressure_Pa = 5: is for an outlet")) << msg;
  msg = error_of(tube_case("", "pressure_Pa = 0"));
  EXPECT_TRUE(has(msg, "[openings.in] flow_rate_m3_s: missing")) << msg;
  msg = error_of(tube_case("flow_rate_m3_s = -1e-13", "pressure_Pa = 0"));
  EXPECT_TRUE(has(msg, "[openings.in] flow_rate_m3_s = -1")) << msg;
  msg = error_of(tube_case("flow_rate_m3_s = 1e-13", "flow_rate_m3_s = 1e-13"));
  EXPECT_TRUE(has(msg, "[openings.out] flow_rate_m3_s = 1e-13: is for an inlet")) << msg;
  msg = error_of(tube_case("flow_rate_m3_s = 1e-13", "flow_fraction = 1.5"));
  EXPECT_TRUE(has(msg, "[openings.out] flow_fraction = 1.5")) << msg;
}

TEST(OpeningConditions, FlowFractionsMustAddUp) {
  // No pressure outlet takes the rest: 0.6 of the inflow would have nowhere to go.
  std::string msg = error_of(tube_case("flow_rate_m3_s = 1e-13", "flow_fraction = 0.4"));
  EXPECT_TRUE(has(msg, "[openings.out] flow_fraction = 0.4: the flow fractions of the outlets sum to 0.4")) << msg;
  // Fractions without an inlet flow rate to take a share of (checked on the structs: the reader needs an inlet rate).
  const Tube t = tube();
  const Opening out{.name = "out", .kind = OpeningKind::outlet, .centre_m = {length, 0, 0}, .normal = {1, 0, 0},
                    .radius_m = radius};
  const auto p = find_conditions_problem({flow_fraction_outlet(out, 1.0)});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->problem.key, "flow_fraction");
  // A type that does not match the kind.
  EXPECT_THROW(check_opening_conditions({pressure_outlet(out, 0.0), flow_rate_inlet(out, 1e-13)}, t, t.bounds()),
               ConfigError);
}

TEST(OpeningConditions, AnOpeningThatDoesNotCutTheWallIsAnError) {
  // The outlet's centre on the x = L face but outside the tube (the box is wider than the tube).
  const Tube t = tube();
  const Box3 box{{0, -2 * radius, -2 * radius}, {length, 2 * radius, 2 * radius}};
  const auto file = ConfigFile::parse(
      "[openings.in]\nkind = \"inlet\"\ncentre_m = [0, 0, 0]\nnormal = [-1, 0, 0]\nradius_m = 10e-6\n"
      "flow_rate_m3_s = 1e-13\n"
      "[openings.out]\nkind = \"outlet\"\ncentre_m = [100e-6, 15e-6, 0]\nnormal = [1, 0, 0]\nradius_m = 2e-6\n"
      "pressure_Pa = 0\n",
      "case.toml");
  try {
    (void)opening_conditions_from_config(file->root().section("openings"), t, box);
    FAIL() << "an outlet beside the tube was accepted";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_TRUE(has(msg, "case.toml: [openings.out] centre_m = [ 0.0001, 1.5e-05, 0 ]")) << msg;
    EXPECT_TRUE(has(msg, "does not cut the geometry's wall")) << msg;
  }
}
