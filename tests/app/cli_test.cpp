// SPDX-License-Identifier: MIT
// The command line as a user meets it: help, version, and exit code 2 with a clear message on bad input.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace {

using Result = hs::test::CommandResult;
Result run(const std::string& args) { return hs::test::run_hemoscale(args); }

fs::path write_case(const std::string& name, const std::string& text) {
  const auto dir = fs::temp_directory_path() / ("hs_cli_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << text;
  return dir;
}

}  // namespace

TEST(Cli, HelpAndVersion) {
  const auto help = run("--help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.output.find("run"), std::string::npos);
  EXPECT_NE(help.output.find("bench"), std::string::npos);
  EXPECT_NE(help.output.find("validate"), std::string::npos);
  const auto version = run("--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_NE(version.output.find("hemoscale"), std::string::npos);
}

TEST(Cli, MissingCaseFileIsExitTwo) {
  const auto r = run("run /nonexistent/case-folder");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("no such case file"), std::string::npos) << r.output;
}

TEST(Cli, MalformedTomlIsExitTwo) {
  const auto r = run("run " + write_case("malformed", "[case\ntype = 1\n").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("malformed TOML"), std::string::npos) << r.output;
}

TEST(Cli, UnknownCaseTypeIsExitTwo) {
  const auto r = run("run " + write_case("unknown_type", "[case]\ntype = \"warp-drive\"\n").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("[case] type = \"warp-drive\""), std::string::npos) << r.output;
}

TEST(Cli, UnknownBenchmarkIsExitTwo) {
  const auto r = run("bench no-such-bench");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("unknown benchmark"), std::string::npos) << r.output;
}

TEST(Cli, BadOptionIsExitTwo) {
  EXPECT_EQ(run("run --no-such-flag x").code, 2);
}

TEST(Cli, PriesTableAndPlotTakeTheJsonFilesName) {
  // Results kept side by side (validate/results/DATE_WHAT.json) must not overwrite each other's table.
  const auto dir = fs::temp_directory_path() / "hs_cli_pries_names";
  fs::remove_all(dir);
  const auto r = run("validate pries --quick --json " + (dir / "first.json").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "first.json")) << r.output;
  EXPECT_TRUE(fs::exists(dir / "first.csv")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "pries_validation.csv"));
  // Issue #25: the validated model takes nothing from Pries 1992: the cells' stress is Einstein's law by default.
  std::ifstream json(dir / "first.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"suspension_viscosity\": \"einstein\""), std::string::npos);
  EXPECT_NE(text.find("\"sensitivity_study\": false"), std::string::npos);
}

TEST(Cli, PriesResumesFromItsArchivedTubes) {
  // Issue #25: the table is a resumable campaign: each tube's summary is archived beside the JSON (X.tubes/) and
  // reused when its model, numerics and seed match; a changed model runs again.
  const auto dir = fs::temp_directory_path() / "hs_cli_pries_resume";
  fs::remove_all(dir);
  const std::string json = (dir / "table.json").string();
  ASSERT_EQ(run("validate pries --quick --json " + json).code, 0);
  EXPECT_TRUE(fs::exists(dir / "table.tubes" / "D30_ht0.10_seed1.json"));
  EXPECT_FALSE(fs::exists(dir / "table.tubes" / "D30_ht0.10_seed1.checkpoint"));   // dropped once the tube is archived
  const auto again = run("validate pries --quick --json " + json);
  EXPECT_EQ(again.code, 0) << again.output;
  std::size_t reused = 0;
  for (std::size_t at = again.output.find("reused"); at != std::string::npos; at = again.output.find("reused", at + 1)) ++reused;
  EXPECT_EQ(reused, 9u) << again.output;   // 3 diameters x 3 hematocrits, one seed with --quick
  const auto other = run("validate pries --quick --suspension-viscosity none --json " + json);
  EXPECT_EQ(other.output.find("reused"), std::string::npos) << other.output;
}

TEST(Cli, PriesWithTheReferencesOwnLawIsLabelledASensitivityStudy) {
  // pries_bulk is Pries 1992's wide-tube law: comparing with Pries 1992 is then no validation, and the output says so.
  const auto dir = fs::temp_directory_path() / "hs_cli_pries_sensitivity";
  fs::remove_all(dir);
  const auto r = run("validate pries --quick --suspension-viscosity pries_bulk --json " + (dir / "bulk.json").string());
  EXPECT_EQ(r.code, 0) << r.output;   // --quick: its checks are the plasma run and finiteness
  EXPECT_NE(r.output.find("a validation: suspension_viscosity = pries_bulk"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("sensitivity study: pries_bulk is Pries 1992's own law"), std::string::npos) << r.output;
  std::ifstream json(dir / "bulk.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"sensitivity_study\": true"), std::string::npos);
}

TEST(Cli, CampaignTakesTheFolderOrItsToml) {
  const fs::path dir = fs::path(HS_SOURCE_DIR) / "cases/campaign/tube-re-rstar";
  auto listing = [&dir] {
    std::string out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) out += e.path().string() + "\n";
    return out;
  };
  const std::string before = listing();
  const auto by_file = run("campaign " + (dir / "campaign.toml").string() + " --status");
  EXPECT_EQ(by_file.code, 0) << by_file.output;
  const auto by_dir = run("campaign " + dir.string() + " --status");
  EXPECT_EQ(by_dir.code, 0) << by_dir.output;
  EXPECT_EQ(by_file.output, by_dir.output);   // the same campaign, the same table
  EXPECT_EQ(listing(), before) << "--status wrote into the campaign folder";
  const fs::path not_a_campaign = dir.parent_path() / "../resolved/tube-poiseuille/case.toml";
  const auto other = run("campaign " + not_a_campaign.string() + " --status");
  EXPECT_EQ(other.code, 2) << other.output;
  EXPECT_NE(other.output.find("give the campaign folder or its campaign.toml"), std::string::npos) << other.output;
}

TEST(Cli, RunHelpListsEveryCaseTypeWithItsLine) {
  const auto r = run("run --help");
  EXPECT_EQ(r.code, 0) << r.output;
  for (const char* type : {"tube-poiseuille", "stretching", "tube-plasma", "tube-cell", "tube-pries", "shear", "migration",
                           "stenosis", "shear-suspension"}) {
    EXPECT_NE(r.output.find(std::string("\n  ") + type + " "), std::string::npos) << type << " not listed:\n" << r.output;
  }
  EXPECT_NE(r.output.find("plasma in a periodic tube, checked against Poiseuille"), std::string::npos) << r.output;
}

TEST(Cli, CampaignTakesQuiet) {
  const fs::path dir = fs::path(HS_SOURCE_DIR) / "cases/campaign/tube-re-rstar";
  const auto quiet = run("campaign " + dir.string() + " --status --quiet");
  EXPECT_EQ(quiet.code, 0) << quiet.output;
  EXPECT_EQ(quiet.output, run("campaign " + dir.string() + " --status").output);   // --status prints the table either way
  EXPECT_NE(run("campaign --help").output.find("--quiet"), std::string::npos);
}

TEST(Cli, ResultsOnStdoutDiagnosticsOnStderr) {
  const fs::path out = fs::temp_directory_path() / "hs_cli_streams";
  fs::remove_all(out);
  const std::string run_case = std::string(HS_BIN) + " run " + HS_SOURCE_DIR + "/cases/resolved/tube-poiseuille --quick --output ";
  const auto stdout_only = hs::test::run_shell("sh -c '" + run_case + out.string() + "/a 2>/dev/null'");
  EXPECT_EQ(stdout_only.code, 0) << stdout_only.output;
  EXPECT_NE(stdout_only.output.find("[--quick] Poiseuille check: u_max"), std::string::npos) << stdout_only.output;
  EXPECT_EQ(stdout_only.output.find("running tube-poiseuille"), std::string::npos) << stdout_only.output;
  const auto stderr_only = hs::test::run_shell("sh -c '" + run_case + out.string() + "/b >/dev/null'");
  EXPECT_EQ(stderr_only.code, 0) << stderr_only.output;
  EXPECT_NE(stderr_only.output.find("running tube-poiseuille"), std::string::npos) << stderr_only.output;
  EXPECT_EQ(stderr_only.output.find("Poiseuille check"), std::string::npos) << stderr_only.output;
  fs::remove_all(out);
}
