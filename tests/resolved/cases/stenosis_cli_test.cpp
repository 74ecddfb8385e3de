// SPDX-License-Identifier: MIT
// The stenosis case through `hemoscale run`: bad input exits with code 2 naming the file and the key; a short --quick
// run writes a finite time series (D_x, D_y, D_z of the resting disc) and a summary with every dimensionless group; the
// passage check passes for a cell that clears the throat and fails for one that does not; a stopped and resumed run
// repeats the uninterrupted time series.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "common/io/csv_writer.hpp"
#include "resolved/cases/cli_case_helpers.hpp"

namespace fs = std::filesystem;

namespace {

fs::path variant(const std::string& name, const std::string& from, const std::string& to) {
  return hs::test::write_case_variant("stenosis/throat-5.5um", "stenosis_" + name, from, to);
}

void expect_input_error(const fs::path& dir, const std::string& key) {
  const hs::test::CliResult r = hs::test::run_hemoscale("run --quiet " + dir.string() + " --output " + (dir / "out").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("case.toml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
}

TEST(StenosisCli, ThroatWiderThanTheChannelIsAnInputError) {
  expect_input_error(variant("wide_throat", "throat_height_m = 5.5e-6", "throat_height_m = 16.0e-6"), "throat_height_m");
}

TEST(StenosisCli, CellReleasedInsideTheConstrictionIsAnInputError) {
  expect_input_error(variant("late_release", "release_x_m = 9.0e-6", "release_x_m = 14.0e-6"), "release_x_m");
}

TEST(StenosisCli, StopBeyondThePeriodicImageIsAnInputError) {
  expect_input_error(variant("far_stop", "stop_x_m = 105.0e-6", "stop_x_m = 140.0e-6"), "stop_x_m");
}

TEST(StenosisCli, UnknownKeyIsAnInputError) {
  expect_input_error(variant("typo", "stop_x_m = 105.0e-6", "stop_x_m = 105.0e-6\nstop_at_m = 1.0"), "stop_at_m");
}

TEST(StenosisCli, QuickRunWritesTheDeformationSeriesAndTheGroups) {
  // 40 samples of 50 us = 2 ms (500 steps): the drive spins up and the cell starts moving; the passage itself takes
  // ~0.15 s (`hemoscale run cases/resolved/stenosis/throat-5.5um`), too long for CI.
  const auto dir = variant("quick", "sample_every_s = 5.0e-4", "sample_every_s = 5.0e-5");
  const auto out = dir / "out";
  const hs::test::CliResult r = hs::test::run_hemoscale("run --quiet --quick " + dir.string() + " --output " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto csv = hs::common::read_csv(out / "timeseries.csv");
  for (const auto& col : csv.columns) {
    const auto v = csv.column(col);
    ASSERT_EQ(v.size(), 40U) << col;
    for (const double x : v) EXPECT_TRUE(std::isfinite(x)) << col;
  }
  // Disc axis along z at release: D_x and D_y near 1 (7.82 um), D_z the thickness over the diameter (~0.3).
  EXPECT_NEAR(csv.column("d_x").front(), 1.0, 0.05);
  EXPECT_NEAR(csv.column("d_y").front(), 1.0, 0.05);
  EXPECT_LT(csv.column("d_z").front(), 0.4);
  EXPECT_GT(csv.column("velocity_x_m_s").back(), 0.0);   // carried downstream
  EXPECT_GT(csv.column("min_wall_gap_m").back(), 0.0);   // still clear of the walls
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  const auto& res = summary["results"];
  for (const char* key : {"reynolds", "ca_throat", "ca_open", "confinement_throat", "confinement_open", "upstream",
                          "throat", "downstream", "d_x_max", "d_x_max_at", "min_wall_gap_m", "flow_rate_m2_s"}) {
    EXPECT_TRUE(res.contains(key)) << key;
  }
  EXPECT_NEAR(res["confinement_throat"].get<double>(), 7.82 / 5.5, 1e-12);
  EXPECT_NEAR(res["flow_rate_target_m2_s"].get<double>(), 2.5e-4 * 15e-6, 1e-18);
  // The drive is calibrated on the plasma alone to the target flow rate; the cell and the start-up ramp take a little.
  EXPECT_NEAR(summary["numerics"]["plasma_calibration"]["drive_m_s2"].get<double>() /
                  summary["numerics"]["plasma_calibration"]["drive_lubrication_m_s2"].get<double>(), 1.0, 0.25);
  EXPECT_FALSE(res["passed_stop_x"].get<bool>());
  // --quick cannot reach the throat: the passage check is skipped and listed, never passed.
  EXPECT_EQ(summary["checks_skipped"].get<int>(), 1) << summary["checks"].dump();
  EXPECT_EQ(summary["checks_failed"].get<int>(), 0) << summary["checks"].dump();
  EXPECT_TRUE(fs::exists(out / "membrane.pvd"));
}

TEST(StenosisCli, ARunThatStopsBeforeTheThroatFailsThePassageCheck) {
  // Negative control of the case's [check]: the same 2 ms as the --quick run, but as a full run (max_time_s cut from
  // 0.4 s): released at x = 9 um, the cell is still upstream of the throat (15-35 um), far from stop_x_m = 105 um,
  // so the passage must be checked, fail, and the run exit 1.
  const auto dir = variant("short", "max_time_s = 0.4 ", "max_time_s = 0.002 ");
  const auto out = dir / "out";
  const hs::test::CliResult r = hs::test::run_hemoscale("run --quiet " + dir.string() + " --output " + out.string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED  the cell passes the throat"), std::string::npos) << r.output;
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["checks_failed"].get<int>(), 1) << summary["checks"].dump();
  EXPECT_FALSE(summary["results"]["passed_stop_x"].get<bool>());
}

TEST(StenosisCli, ACellThatClearsTheThroatPassesThePassageCheck) {
  // The passing side of the case's [check], end to end: the shipped 8.5 um throat with the flow 4x faster (1 mm/s;
  // Ca at the throat 2.1 instead of 0.5: the same time step, a quarter of the steps) and stop_x_m 40 um, 5 um past the
  // constriction's exit (35 um). The centroid passes it after ~0.019 s (measured), well inside the 0.06 s cap. ~25 s of
  // one core; the committed flow's passage (0.14 s simulated to 105 um) takes ~10 min and is not in CTest.
  std::string text = hs::test::replaced(hs::test::shipped_case_text("stenosis"), "mean_velocity_m_s = 2.5e-4 ",
                                        "mean_velocity_m_s = 1.0e-3 ");
  text = hs::test::replaced(text, "stop_x_m = 105.0e-6 ", "stop_x_m = 40.0e-6 ");
  text = hs::test::replaced(text, "max_time_s = 0.4 ", "max_time_s = 0.06 ");
  text = hs::test::replaced(text, "vtk_every_s = 0.01 ", "vtk_every_s = 0.0 ");
  const fs::path dir = hs::test::write_case_text("stenosis_passes", text);
  const auto out = dir / "out";
  const hs::test::CliResult r = hs::test::run_hemoscale("run --quiet " + dir.string() + " --output " + out.string());
  EXPECT_EQ(r.code, 0) << r.output;
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["checks_failed"].get<int>(), 0) << summary["checks"].dump();
  EXPECT_EQ(summary["checks_skipped"].get<int>(), 0) << summary["checks"].dump();
  EXPECT_TRUE(summary["results"]["passed_stop_x"].get<bool>());
  // It passed through the throat, not around it: no membrane vertex inside a wall in any sample.
  EXPECT_EQ(summary["results"]["samples_with_vertex_in_wall"].get<int>(), 0);
}

TEST(StenosisCli, StoppedAndResumedRunGivesTheUninterruptedTimeSeries) {
  // 40 samples of 48 us (--quick) at once versus 20 then --resume to 40: the shared cell checkpoint (populations, force
  // field, membrane, markers, samples) must continue bit for bit; the drive is recalibrated identically on resume.
  const auto with_cap = [](const std::string& name, const char* cap) {
    return variant(name, "max_time_s = 0.4 ", std::string("max_time_s = ") + cap + " ");
  };
  const auto fine_samples = [](const fs::path& dir) {
    const auto path = dir / "case.toml";
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("sample_every_s = 5.0e-4"), 23, "sample_every_s = 5.0e-5");
    std::ofstream(path) << text;
  };
  const auto whole = with_cap("resume_whole", "0.002");
  const auto part = with_cap("resume_part", "0.00096");   // 20 samples of 12 steps (48 us, whole membrane steps)
  const auto rest = with_cap("resume_rest", "0.002");
  for (const auto& dir : {whole, part, rest}) fine_samples(dir);
  const auto run = [](const fs::path& dir, const fs::path& out, const std::string& extra) {
    const hs::test::CliResult r =
        hs::test::run_hemoscale("run --quiet --quick " + dir.string() + " --output " + out.string() + extra);
    EXPECT_EQ(r.code, 0) << r.output;
  };
  run(whole, whole / "out", "");
  run(part, part / "out", "");
  run(rest, part / "out", " --resume");
  const auto a = hs::common::read_csv(whole / "out" / "timeseries.csv");
  const auto b = hs::common::read_csv(part / "out" / "timeseries.csv");
  for (const auto& col : a.columns) {
    const auto x = a.column(col);
    const auto y = b.column(col);
    ASSERT_EQ(x.size(), y.size()) << col;
    for (std::size_t k = 0; k < x.size(); ++k) EXPECT_EQ(y[k], x[k]) << col << " row " << k;
  }
}

}  // namespace
