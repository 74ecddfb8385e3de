// SPDX-License-Identifier: MIT
// Strict case-file reading: every bad input is one ConfigError naming file, key, value and what is allowed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"

using hs::common::ConfigError;
using hs::common::ConfigFile;

namespace {

std::string error_of(const std::string& toml, void (*read)(ConfigFile&)) {
  try {
    auto f = ConfigFile::parse(toml, "case.toml");
    read(*f);
    f->finish();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

void read_fluid(ConfigFile& f) {
  auto fluid = f.root().section("fluid");
  (void)fluid.positive("kinematic_viscosity_m2_s");
  (void)fluid.positive_or("density_kg_m3", 1025.0);
}

}  // namespace

TEST(ConfigFile, ReadsValuesAndFillsDefaults) {
  auto f = ConfigFile::parse("[fluid]\nkinematic_viscosity_m2_s = 1e-6\n", "case.toml");
  auto fluid = f->root().section("fluid");
  EXPECT_DOUBLE_EQ(fluid.positive("kinematic_viscosity_m2_s"), 1e-6);
  EXPECT_DOUBLE_EQ(fluid.positive_or("density_kg_m3", 1025.0), 1025.0);
  EXPECT_NO_THROW(f->finish());
  EXPECT_EQ(f->resolved()["fluid"]["density_kg_m3"].value<double>(), 1025.0);
}

TEST(ConfigFile, UnknownKeyNamesFileKeyAndAllowedKeys) {
  const auto msg = error_of("[fluid]\nkinematic_viscosity_m2_s = 1e-6\ndensty_kg_m3 = 1000\n", read_fluid);
  EXPECT_NE(msg.find("case.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("densty_kg_m3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("density_kg_m3"), std::string::npos) << msg;   // the allowed spelling is listed
}

TEST(ConfigFile, NegativeViscosityNamesKeyAndValue) {
  const auto msg = error_of("[fluid]\nkinematic_viscosity_m2_s = -1e-6\n", read_fluid);
  EXPECT_NE(msg.find("[fluid] kinematic_viscosity_m2_s = -1e-06"), std::string::npos) << msg;
  EXPECT_NE(msg.find("> 0"), std::string::npos) << msg;
}

TEST(ConfigFile, WrongTypeAndMissingKeyAreErrors) {
  EXPECT_NE(error_of("[fluid]\nkinematic_viscosity_m2_s = \"x\"\n", read_fluid).find("must be a number"), std::string::npos);
  EXPECT_NE(error_of("[fluid]\n", read_fluid).find("missing"), std::string::npos);
  EXPECT_NE(error_of("x = 1\n", read_fluid).find("missing section"), std::string::npos);
}

TEST(ConfigFile, MalformedTomlGivesLineAndColumn) {
  const auto msg = error_of("[fluid\nx = 1\n", read_fluid);
  EXPECT_NE(msg.find("case.toml:1:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("malformed TOML"), std::string::npos) << msg;
}

TEST(ConfigFile, MissingFileIsAConfigError) {
  EXPECT_THROW(ConfigFile::load("/nonexistent/case.toml"), ConfigError);
}

TEST(ConfigFile, RedundantKeysAreRejected) {
  auto f = ConfigFile::parse("[numerics]\ntau = 1.0\ntime_step_s = 1e-7\n", "case.toml");
  auto n = f->root().section("numerics");
  EXPECT_THROW(n.forbid_together("tau", "time_step_s", "dt follows from dx, tau and nu"), ConfigError);
}

TEST(ConfigFile, RangesAndChoices) {
  auto f = ConfigFile::parse("tau = 0.5\nmode = \"bgk\"\nn = 3.5\n", "case.toml");
  auto r = f->root();
  EXPECT_THROW((void)r.greater_than("tau", 0.5), ConfigError);
  EXPECT_THROW((void)r.one_of("mode", {"trt", "mrt"}), ConfigError);
  EXPECT_THROW((void)r.integer_in("n", 0, 10), ConfigError);
}

TEST(ConfigFile, UnknownKeySuggestsTheClosestAllowedKey) {
  const auto msg = error_of("[fluid]\nkinematic_viscosity_m2_s = 1e-6\ndensty_kg_m3 = 1000\n", read_fluid);
  EXPECT_NE(msg.find("[fluid] densty_kg_m3: unknown key (did you mean density_kg_m3?"), std::string::npos) << msg;
  const auto swapped = error_of("[fluid]\nkinematic_viscosity_m2_s = 1e-6\ndesnity_kg_m3 = 1000\n", read_fluid);
  EXPECT_NE(swapped.find("did you mean density_kg_m3?"), std::string::npos) << swapped;   // adjacent swap: 1 edit
}

TEST(ConfigFile, MissingKeyNamesTheCloseUnknownKeyPresent) {
  const auto msg = error_of("[fluid]\nkinematic_viscosity_m2s = 1e-6\n", read_fluid);
  EXPECT_NE(msg.find("case.toml: [fluid] kinematic_viscosity_m2_s: missing"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the file has kinematic_viscosity_m2s, did you mean kinematic_viscosity_m2_s?"), std::string::npos)
      << msg;
}

TEST(ConfigFile, FarOffKeyGetsNoSuggestion) {
  const auto unknown = error_of("[fluid]\nkinematic_viscosity_m2_s = 1e-6\ncolour = 3\n", read_fluid);
  EXPECT_NE(unknown.find("[fluid] colour: unknown key (allowed here:"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find("did you mean"), std::string::npos) << unknown;
  const auto missing = error_of("[fluid]\nviscosity = 1e-6\n", read_fluid);
  EXPECT_NE(missing.find("kinematic_viscosity_m2_s: missing"), std::string::npos) << missing;
  EXPECT_EQ(missing.find("did you mean"), std::string::npos) << missing;
}

// case.resolved.toml quotes a float as the user wrote it (#31: 1e-05, not 1.0000000000000001e-05), and it reads back
// to the same double; integers and strings that look like numbers are left alone.
TEST(ConfigFile, ResolvedCaseWritesShortestFloatsThatRoundTrip) {
  const auto dir = std::filesystem::temp_directory_path() / "hs_resolved_floats";
  std::filesystem::create_directories(dir);
  auto config = hs::common::ConfigFile::parse(
      "[numerics]\ndx_m = 1e-05\nnu = 1.0e-6\nthird = 0.3333333333333333\nsteps = 100\nlist = [2.5e-05, 0.1, 3]\n"
      "name = \"1.0000000000000001e-05\"\nday_label = '1979-05-27 or 2.50'\n",
      (dir / "case.toml").string());
  auto numerics = config->root().section("numerics");
  (void)numerics.positive("dx_m");
  (void)numerics.positive("nu");
  (void)numerics.positive("third");
  (void)numerics.integer_in("steps", 1, 1000);
  (void)numerics.numbers_in("list", 0.0, 10.0, 3);
  (void)numerics.string("name");
  (void)numerics.string("day_label");
  config->write_resolved(dir / "case.resolved.toml", false, false);
  std::ostringstream text;
  text << std::ifstream(dir / "case.resolved.toml").rdbuf();
  const std::string s = text.str();
  for (const char* expected : {"dx_m = 1e-05\n", "nu = 1e-06\n", "third = 0.3333333333333333\n", "steps = 100\n",
                               "2.5e-05", "0.1", "1.0000000000000001e-05", "1979-05-27 or 2.50"}) {
    EXPECT_NE(s.find(expected), std::string::npos) << expected << " in\n" << s;
  }
  const auto back = toml::parse_file((dir / "case.resolved.toml").string());
  EXPECT_EQ(back["numerics"]["dx_m"].value<double>(), 1e-05);
  EXPECT_EQ(back["numerics"]["third"].value<double>(), 0.3333333333333333);
  EXPECT_EQ(back["numerics"]["list"][0].value<double>(), 2.5e-05);
  std::filesystem::remove_all(dir);
}
