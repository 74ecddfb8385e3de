// SPDX-License-Identifier: MIT
// The tube-poiseuille case as a user meets it through `hemoscale run`: bad inputs give exit code 2 with a message
// naming file and key; a good --quick run passes its Poiseuille check and writes a parseable summary.json.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using Result = hs::test::CommandResult;
Result run(const std::string& args) { return hs::test::run_hemoscale(args); }

/// The shipped case file with one line replaced (`from` must occur in it) or text appended.
fs::path write_variant(const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(fs::path(HS_SOURCE_DIR) / "cases/resolved/tube-poiseuille/case.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!from.empty()) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
  }
  const auto dir = fs::temp_directory_path() / ("hs_tube_poiseuille_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << text;
  return dir;
}

void expect_config_error(const std::string& name, const std::string& from, const std::string& to,
                         const std::string& key_text) {
  const auto dir = write_variant(name, from, to);
  const Result r = run("run --quiet " + dir.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find((dir / "case.toml").string()), std::string::npos) << "file not named: " << r.output;
  EXPECT_NE(r.output.find(key_text), std::string::npos) << "key not named: " << r.output;
}

}  // namespace

TEST(TubePoiseuilleCase, UnknownKeyIsExitTwo) {
  expect_config_error("unknown_key", "reynolds = 0.5", "reynolds = 0.5\nreynold_number = 0.5", "reynold_number");
}

TEST(TubePoiseuilleCase, NegativeViscosityIsExitTwo) {
  expect_config_error("negative_nu", "kinematic_viscosity_m2_s = 1.0e-6", "kinematic_viscosity_m2_s = -1.0e-6",
                      "[fluid] kinematic_viscosity_m2_s");
}

TEST(TubePoiseuilleCase, TauAtOneHalfIsExitTwo) {
  expect_config_error("tau_half", "tau = 2.5 ", "tau = 0.5 ", "[numerics] tau");
}

TEST(TubePoiseuilleCase, MachTooHighIsExitTwo) {
  expect_config_error("mach", "reynolds = 0.5", "reynolds = 500.0", "[flow] reynolds");
  const auto dir = write_variant("mach_msg", "reynolds = 0.5", "reynolds = 500.0");
  EXPECT_NE(run("run --quiet " + dir.string()).output.find("Mach"), std::string::npos);
}

TEST(TubePoiseuilleCase, TubeLargerThanBoxIsExitTwo) {
  expect_config_error("box", "# box_width_m = 54.0e-6", "box_width_m = 40.0e-6", "[geometry] box_width_m");
}

TEST(TubePoiseuilleCase, GivingTheTimeStepTooIsExitTwo) {
  expect_config_error("dt", "tau = 2.5 ", "time_step_s = 1e-7\ntau = 2.5 ", "time_step_s");
}

TEST(TubePoiseuilleCase, QuickRunPassesAndWritesSummary) {
  const auto out = fs::temp_directory_path() / "hs_tube_poiseuille_quick_run";
  fs::remove_all(out);
  const Result r = run("run --quiet --quick -o " + out.string() + " " + HS_SOURCE_DIR + "/cases/resolved/tube-poiseuille");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("Poiseuille check"), std::string::npos) << r.output;
  std::ifstream in(out / "summary.json");
  const auto s = nlohmann::json::parse(in);
  const auto& res = s.at("results");
  EXPECT_TRUE(res.at("converged").get<bool>());
  EXPECT_TRUE(s.at("passed").get<bool>()) << s.at("checks").dump();
  EXPECT_EQ(s.at("checks").size(), 3U);
  // Corrected Bouzidi walls at R = 10 lattice spacings: measured 0.12 % (u_max), 0.36 % (flow rate).
  EXPECT_LT(res.at("u_max_rel_error").get<double>(), 0.01);
  EXPECT_LT(res.at("flow_rate_rel_error").get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(s.at("groups").at("reynolds").get<double>(), 0.5);
  EXPECT_LT(s.at("groups").at("lattice_mach").get<double>(), 0.1);
  EXPECT_TRUE(s.contains("provenance"));
  for (const char* f : {"units.txt", "case.resolved.toml", "timeseries.csv", "fields.pvd", "log.txt"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_FALSE(fs::is_empty(out / "vtk"));
}
