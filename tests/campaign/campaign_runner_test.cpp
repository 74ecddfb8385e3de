// SPDX-License-Identifier: MIT
// A real (small) campaign of tube-poiseuille runs: every run done once, a bad point recorded as failed with
// its reason, the dataset assembled, and a second invocation on the finished folder doing nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"
#include "support/background_run.hpp"
#include "resolved/cases/case_text_helpers.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "campaign/campaign_spec.hpp"
#include "campaign/case_template.hpp"
#include "campaign/invocation_log.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"

namespace fs = std::filesystem;

namespace {

using Result = hs::test::CommandResult;
Result run(const std::string& args) { return hs::test::run_hemoscale(args); }

/// A 5-lattice-spacing tube: each run reaches steady state in about a hundred steps.
fs::path make_campaign(const std::string& name, const std::string& reynolds_values, const std::string& campaign_lines = "") {
  const auto dir = fs::temp_directory_path() / ("hs_campaign_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << R"([case]
type = "tube-poiseuille"
[geometry]
radius_m = 5.0e-6
length_m = 4.0e-6
[fluid]
density_kg_m3 = 1025.0
kinematic_viscosity_m2_s = 1.0e-6
[flow]
reynolds = 0.5
[numerics]
dx_m = 1.0e-6
tau = 2.5
[output]
vtk_frames = 1
)";
  std::ofstream(dir / "campaign.toml") << "[campaign]\nname = \"test\"\ntemplate = \"case.toml\"\njobs = 2\n"
                                       << campaign_lines << "[grid.re]\nkey = \"flow.reynolds\"\nvalues = " << reynolds_values << "\n"
                                       << "[dataset]\nfile = \"dataset.csv\"\nrow_axes = \"re\"\n"
                                       << "[dataset.columns.u_max_m_s]\npointer = \"/results/u_max_m_s\"\n"
                                       << "pointer_before_schema_1 = \"/u_max_m_s\"\n"
                                       << "[dataset.columns.u_max_analytic_m_s]\npointer = \"/results/u_max_analytic_m_s\"\n";
  return dir;
}

}  // namespace

TEST(Campaign, RunsEveryPointOnceAndAssemblesTheDataset) {
  const auto dir = make_campaign("ok", "[0.1, 0.2]");
  const auto first = run("campaign " + dir.string());
  ASSERT_EQ(first.code, 0) << first.output;
  const auto table = hs::common::read_csv(dir / "dataset.csv");
  ASSERT_EQ(table.rows.size(), 2u);
  // Poiseuille at R = 5 lattice spacings: the run's own check holds u_max to its tolerance; here only that the
  // dataset carries the run's numbers (not a re-derivation): U_max = Re nu / D.
  EXPECT_NEAR(table.column("u_max_analytic_m_s")[0], 0.1 * 1e-6 / 10e-6, 1e-15);
  EXPECT_NEAR(table.column("u_max_m_s")[1] / table.column("u_max_analytic_m_s")[1], 1.0, 0.05);
  const auto mtime = fs::last_write_time(dir / "runs" / "re-0.1" / "status.json");
  const auto second = run("campaign " + dir.string());   // a finished campaign: nothing to do, exit 0
  EXPECT_EQ(second.code, 0) << second.output;
  EXPECT_EQ(fs::last_write_time(dir / "runs" / "re-0.1" / "status.json"), mtime);
  EXPECT_NE(second.output.find("2 done"), std::string::npos) << second.output;
  // The campaign's wall time: one invocation ran the two runs; the second, with nothing to do, is not recorded.
  const auto totals = hs::campaign::read_invocation_totals(dir / "runs" / "invocations.json");
  EXPECT_EQ(totals.invocations, 1);
  EXPECT_GT(totals.wall_s, 0.0);
  EXPECT_NE(second.output.find("over 1 invocation"), std::string::npos) << second.output;
}

TEST(Campaign, AFreshCloneGoesOnFromTheArchive) {
  // The run folders are scratch (git-ignored); the archive is what gets committed. A clone without runs/ must find
  // every finished run done, rebuild the dataset from the archived summaries, and run nothing again.
  const auto dir = make_campaign("archive", "[0.1, 0.2]", "archive = \"archive\"\n");
  ASSERT_EQ(run("campaign " + dir.string()).code, 0);
  for (const char* file : {"summary.json", "status.json", "timeseries.csv.gz"}) {
    EXPECT_TRUE(fs::exists(dir / "archive" / "re-0.1" / file)) << file;
  }
  EXPECT_EQ(hs::campaign::read_invocation_totals(dir / "archive" / "invocations.json").invocations, 1);
  const auto rows = hs::common::read_csv(dir / "dataset.csv").column("u_max_m_s");
  fs::remove_all(dir / "runs");
  fs::remove(dir / "dataset.csv");
  const auto looked = run("campaign " + dir.string() + " --status");   // the archived runs' wall time counts
  EXPECT_NE(looked.output.find("done*"), std::string::npos) << looked.output;
  EXPECT_EQ(looked.output.find("runs so far 0.0s"), std::string::npos) << looked.output;
  // A run archived before summary.json's schema 1 (flat, no schema_version) is read at pointer_before_schema_1.
  const fs::path archived = dir / "archive" / "re-0.1" / "summary.json";
  const auto current = nlohmann::json::parse(std::ifstream(archived));
  nlohmann::json flat = current["results"];
  flat["provenance"] = current["provenance"];
  std::ofstream(archived) << flat.dump(2);
  const auto again = run("campaign " + dir.string());
  EXPECT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("2 done"), std::string::npos) << again.output;
  EXPECT_FALSE(fs::exists(dir / "runs" / "re-0.1" / "console.txt")) << "a restored run must not run again";
  EXPECT_EQ(hs::common::read_csv(dir / "dataset.csv").column("u_max_m_s"), rows);
  // A reopened run leaves the archive too: a clone made now must not bring its old result back as done.
  EXPECT_EQ(run("campaign " + dir.string() + " --reopen-done --max-runs 0").code, 0);
  EXPECT_FALSE(fs::exists(dir / "archive" / "re-0.1" / "status.json"));
  EXPECT_FALSE(fs::exists(dir / "archive" / "re-0.1" / "summary.json"));
}

TEST(Campaign, ReopenedRunsGoAgainAndLeaveTheDatasetUntilTheyFinish) {
  const auto dir = make_campaign("reopen", "[0.1, 0.2]");
  ASSERT_EQ(run("campaign " + dir.string()).code, 0);
  // --max-runs 0 starts nothing: the reopened runs wait (tube-poiseuille keeps no checkpoint, so they will start
  // afresh), and the dataset lists no row until they finish again.
  const auto held = run("campaign " + dir.string() + " --reopen-done --max-runs 0");
  EXPECT_EQ(held.code, 0) << held.output;
  EXPECT_NE(held.output.find("0 done, 0 failed, 0 running, 0 resumable, 2 pending"), std::string::npos) << held.output;
  EXPECT_EQ(hs::common::read_csv(dir / "dataset.csv").rows.size(), 0u);
  // The next invocation runs them: done again, rows back, the first output kept beside the new one.
  const auto again = run("campaign " + dir.string());
  EXPECT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("2 done"), std::string::npos) << again.output;
  EXPECT_EQ(hs::common::read_csv(dir / "dataset.csv").rows.size(), 2u);
  EXPECT_TRUE(fs::exists(dir / "runs" / "re-0.1" / "output.attempt-1"));
}

TEST(Campaign, AFailedRunIsRecordedAndDoesNotStopTheOthers) {
  const auto dir = make_campaign("fail", "[0.2, 5000.0]");   // Re = 5000: lattice Mach far above 0.1
  const auto r = run("campaign " + dir.string());
  EXPECT_EQ(r.code, 1) << r.output;
  const auto status = run("campaign " + dir.string() + " --status");
  EXPECT_NE(status.output.find("1 done, 1 failed"), std::string::npos) << status.output;
  EXPECT_NE(status.output.find("Mach"), std::string::npos) << status.output;   // the reason, from the run's message
  EXPECT_NE(status.output.find("wall time of the runs so far"), std::string::npos) << status.output;
  EXPECT_EQ(hs::common::read_csv(dir / "dataset.csv").rows.size(), 1u);
  // A retry starts afresh and keeps a failed attempt's output beside it (outputs are never overwritten). This run
  // fails while reading its case, before it has an output folder, so one is left here as a later failure would.
  fs::create_directories(dir / "runs" / "re-5000" / "output");
  std::ofstream(dir / "runs" / "re-5000" / "output" / "log.txt") << "an earlier attempt\n";
  // The retry starts from campaign.toml as it is now: an override added after the failure reaches the run's case.
  std::ofstream(dir / "campaign.toml", std::ios::app)
      << "[override.retry]\nwhen = { re = 5000.0 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"added after it failed\"\n";
  const auto retry = run("campaign " + dir.string() + " --retry-failed");
  EXPECT_EQ(retry.code, 1) << retry.output;
  EXPECT_NE(hs::test::file_text(dir / "runs" / "re-5000" / "case.toml").find("tau = 3.5"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "runs" / "re-5000" / "output.attempt-1" / "log.txt"));
  const auto again = run("campaign " + dir.string() + " --status");
  EXPECT_NE(again.output.find("Mach"), std::string::npos) << again.output;
}

TEST(Campaign, RowValuesFollowTheHeaderOrder) {
  // Axes are stored by name (a_tau before re); the dataset's row axes are listed as "re, a_tau".
  const auto dir = make_campaign("order", "[0.1]");
  std::string text;
  {
    std::ifstream in(dir / "campaign.toml");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string from = "row_axes = \"re\"";
  text.replace(text.find(from), from.size(), "row_axes = \"re, a_tau\"");
  text += "[grid.a_tau]\nkey = \"numerics.tau\"\nvalues = [2.5]\n";
  std::ofstream(dir / "campaign.toml") << text;
  ASSERT_EQ(run("campaign " + dir.string()).code, 0);
  const auto table = hs::common::read_csv(dir / "dataset.csv");
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(table.column("re")[0], 0.1);
  EXPECT_DOUBLE_EQ(table.column("a_tau")[0], 2.5);
}

TEST(Campaign, BadCampaignFileIsAConfigError) {
  const auto dir = make_campaign("bad", "[0.1]");
  std::ofstream(dir / "campaign.toml", std::ios::app) << "[dataset.columns.x]\npointer = \"/x\"\nonly_axis = \"nope\"\n";
  EXPECT_THROW(hs::campaign::read_campaign_spec(dir), hs::common::ConfigError);
}

TEST(Campaign, AnOverrideChangesOnlyTheRunsItMatchesAndSaysWhy) {
  const auto dir = make_campaign("override", "[0.1, 0.2]");
  std::ofstream(dir / "campaign.toml", std::ios::app)
      << "[override.slow]\nwhen = { re = 0.2 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"a test reason\"\n";
  const auto spec = hs::campaign::read_campaign_spec(dir);
  ASSERT_EQ(spec.overrides.size(), 1u);
  for (const auto& point : hs::campaign::grid_points(spec)) {
    const auto file = dir / (hs::campaign::run_name(spec, point) + ".toml");
    hs::campaign::write_run_case(spec, point, file);
    std::ifstream in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const bool matched = std::get<double>(point.values[0]) == 0.2;
    EXPECT_EQ(text.find("tau = 3.5") != std::string::npos, matched) << text;
    EXPECT_EQ(text.find("tau = 2.5") != std::string::npos, !matched) << text;
    EXPECT_EQ(text.find("# [override.slow] numerics.tau = 3.5: a test reason") != std::string::npos, matched) << text;
  }
}

TEST(Campaign, AnOverrideOfACountKeepsItAnInteger) {
  // The case readers require counts (output.vtk_frames, numerics.membrane_every) as TOML integers: an override of a key
  // the template holds as an integer writes an integer, and refuses a fraction.
  const auto dir = make_campaign("override_integer", "[0.1, 0.2]");
  std::ofstream(dir / "campaign.toml", std::ios::app)
      << "[override.frames]\nwhen = { re = 0.2 }\nkey = \"output.vtk_frames\"\nvalue = 2\nwhy = \"a count\"\n";
  const auto spec = hs::campaign::read_campaign_spec(dir);
  const auto points = hs::campaign::grid_points(spec);
  hs::campaign::write_run_case(spec, points[1], dir / "run.toml");
  std::ifstream in(dir / "run.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("vtk_frames = 2\n"), std::string::npos) << text;
  const auto fraction = make_campaign("override_fraction", "[0.1, 0.2]");
  std::ofstream(fraction / "campaign.toml", std::ios::app)
      << "[override.frames]\nwhen = { re = 0.2 }\nkey = \"output.vtk_frames\"\nvalue = 2.5\nwhy = \"a count\"\n";
  const auto bad = hs::campaign::read_campaign_spec(fraction);
  EXPECT_THROW(hs::campaign::write_run_case(bad, hs::campaign::grid_points(bad)[1], fraction / "run.toml"),
               hs::common::ConfigError);
}

/// True when a campaign on re = [0.1, 0.2] with `overrides` appended to its campaign.toml is refused as bad input.
bool refused(const std::string& name, const std::string& overrides) {
  const auto dir = make_campaign(name, "[0.1, 0.2]");
  std::ofstream(dir / "campaign.toml", std::ios::app) << overrides;
  try {
    (void)hs::campaign::read_campaign_spec(dir);
  } catch (const hs::common::ConfigError&) {
    return true;
  }
  return false;
}

TEST(Campaign, AnOverrideThatMatchesNoRunIsAConfigError) {
  EXPECT_TRUE(refused("override_axis", "[override.x]\nwhen = { r_star = 0.2 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"w\"\n"));
  EXPECT_TRUE(refused("override_value", "[override.x]\nwhen = { re = 0.3 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"w\"\n"));
}

TEST(Campaign, AnOverrideMayNotChangeAGridValueOrFightAnother) {
  EXPECT_TRUE(refused("override_grid_key",
                      "[override.x]\nwhen = { re = 0.1 }\nkey = \"flow.reynolds\"\nvalue = 0.2\nwhy = \"w\"\n"));
  EXPECT_TRUE(refused("override_two", "[override.a]\nwhen = { re = 0.1 }\nkey = \"numerics.tau\"\nvalue = 3.0\nwhy = \"w\"\n"
                                      "[override.b]\nwhen = { re = 0.1 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"w\"\n"));
  EXPECT_FALSE(refused("override_two_apart",
                       "[override.a]\nwhen = { re = 0.1 }\nkey = \"numerics.tau\"\nvalue = 3.0\nwhy = \"w\"\n"
                       "[override.b]\nwhen = { re = 0.2 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"w\"\n"));
  EXPECT_TRUE(refused("override_why",
                      "[override.x]\nwhen = { re = 0.1 }\nkey = \"numerics.tau\"\nvalue = 3.0\nwhy = \"one\\nre = 9\"\n"));
}

TEST(Campaign, ARunNotYetStartedFollowsAnOverrideAddedLater) {
  const auto dir = make_campaign("override_later", "[0.1, 0.2]");
  ASSERT_EQ(run("campaign " + dir.string() + " --max-runs 1").code, 0);   // re 0.1 done; re 0.2 not started
  std::ofstream(dir / "campaign.toml", std::ios::app)
      << "[override.later]\nwhen = { re = 0.2 }\nkey = \"numerics.tau\"\nvalue = 3.5\nwhy = \"added later\"\n"
      << "[override.too_late]\nwhen = { re = 0.1 }\nkey = \"numerics.tau\"\nvalue = 3.0\nwhy = \"after its run\"\n";
  ASSERT_EQ(run("campaign " + dir.string() + " --max-runs 0").code, 0);   // prepares the runs, starts none
  const auto text = [&](const char* name) {
    std::ifstream in(dir / "runs" / name / "case.toml");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  EXPECT_NE(text("re-0.2").find("tau = 3.5"), std::string::npos) << text("re-0.2");
  EXPECT_EQ(text("re-0.1").find("tau = 3.0"), std::string::npos) << "a finished run keeps the case it ran: " << text("re-0.1");
}

TEST(Campaign, AStoppedCampaignLeavesItsRunsResumable) {
  // SIGTERM to the campaign (Ctrl-C, `kill`, a batch system's time limit): it asks each running run to stop, each
  // writes its checkpoint, and the campaign exits with 128 + 15 leaving the runs resumable, not failed.
  const auto dir = fs::temp_directory_path() / "hs_campaign_stop";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << hs::test::replaced(hs::test::shipped_case_text("tube-drag"),
                                                        "max_jeffery_periods = 6 ", "max_time_s = 0.05 ");
  std::ofstream(dir / "campaign.toml") << "[campaign]\nname = \"stop\"\ntemplate = \"case.toml\"\njobs = 1\n"
                                       << "archive = \"archive\"\n"
                                       << "[grid.re]\nkey = \"flow.reynolds\"\nvalues = [0.5]\n"
                                       << "[dataset]\nfile = \"dataset.csv\"\nrow_axes = \"re\"\n"
                                       << "[dataset.columns.cd_mean]\npointer = \"/results/cd_mean\"\n";
  const auto series = dir / "runs" / "re-0.5" / "output" / "timeseries.csv";
  const pid_t pid = hs::test::start_hemoscale({"campaign", dir.string()}, dir / "console.txt");
  const bool sampling = hs::test::wait_until([&] { return hs::test::line_count(series) >= 3; }, std::chrono::seconds(120));
  // Meanwhile --status shows the run as running, and a second campaign on the folder leaves it to the first.
  const auto running = run("campaign " + dir.string() + " --status");
  const auto second = run("campaign " + dir.string());
  kill(pid, SIGTERM);
  ASSERT_TRUE(sampling) << hs::test::file_text(dir / "console.txt");
  EXPECT_NE(running.output.find("1 running"), std::string::npos) << running.output;
  EXPECT_EQ(second.code, 0) << second.output;
  EXPECT_EQ(hs::test::wait_for_exit(pid), 128 + SIGTERM) << hs::test::file_text(dir / "console.txt");
  EXPECT_TRUE(fs::exists(series.parent_path() / "checkpoint"));
  const auto status = run("campaign " + dir.string() + " --status");
  EXPECT_NE(status.output.find("1 resumable"), std::string::npos) << status.output;
  // ... with how far it got: the last sample's time, from its time series.
  std::ifstream in(series);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  const auto reached = fmt::format("{:.3g} s", std::strtod(last.c_str(), nullptr));
  EXPECT_NE(status.output.find(reached), std::string::npos) << reached << "\n" << status.output;
  // The stopped campaign also put the run's checkpoint into its (committed) archive: a fresh clone without runs/
  // gets it back byte for byte, so the run resumes there instead of starting over.
  const auto checkpoint = series.parent_path() / "checkpoint" / "state.rank0000.bin";
  const std::string saved = hs::test::file_text(checkpoint);
  EXPECT_TRUE(fs::exists(dir / "archive" / "re-0.5" / "checkpoint" / "state.rank0000.bin.gz"));
  fs::remove_all(dir / "runs");
  const auto archived = run("campaign " + dir.string() + " --status");   // --status only looks
  EXPECT_NE(archived.output.find("resumable*"), std::string::npos) << archived.output;
  EXPECT_FALSE(fs::exists(dir / "runs" / "re-0.5")) << "--status wrote a run folder";
  const auto restored = run("campaign " + dir.string() + " --max-runs 0");   // restores, starts nothing
  EXPECT_EQ(restored.code, 0) << restored.output;
  EXPECT_EQ(hs::test::file_text(checkpoint), saved);
  EXPECT_NE(run("campaign " + dir.string() + " --status").output.find("1 resumable"), std::string::npos);
  // A truncated archive file is one clear error (exit 2), and the next try restores again once it is fixed.
  fs::remove_all(dir / "runs");
  const auto gz = dir / "archive" / "re-0.5" / "checkpoint" / "state.rank0000.bin.gz";
  const std::string whole = hs::test::file_text(gz);
  std::ofstream(gz, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);
  const auto truncated = run("campaign " + dir.string() + " --max-runs 0");
  EXPECT_EQ(truncated.code, 2) << truncated.output;
  EXPECT_NE(truncated.output.find("not a complete gzip file"), std::string::npos) << truncated.output;
  std::ofstream(gz, std::ios::binary | std::ios::trunc) << whole;
  EXPECT_EQ(run("campaign " + dir.string() + " --max-runs 0").code, 0);
  EXPECT_EQ(hs::test::file_text(checkpoint), saved);
}
