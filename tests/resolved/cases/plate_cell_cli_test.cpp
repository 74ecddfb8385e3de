// SPDX-License-Identifier: MIT
// The shear and migration cases through `hemoscale run`: a short --quick run of each writes finite time series and a
// summary with the flow mode and every dimensionless group; a stopped and resumed shear run repeats the series.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "common/io/csv_writer.hpp"
#include "resolved/cases/cli_case_helpers.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& args, std::string* output = nullptr) {
  const hs::test::CliResult r = hs::test::run_hemoscale(args);
  if (output != nullptr) *output = r.output;
  return r.code;
}

fs::path write_variant(const std::string& folder, const std::string& name, const std::string& from, const std::string& to) {
  // The folder is part of the name: ctest -j runs the shear and migration tests at the same time.
  std::string tag = folder;
  for (char& ch : tag) ch = ch == '/' ? '_' : ch;
  return hs::test::write_case_variant(folder, "plate_cell_" + tag + "_" + name, from, to);
}

nlohmann::json summary(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

void expect_finite_series(const fs::path& out, std::size_t rows) {
  const auto csv = hs::common::read_csv(out / "timeseries.csv");
  for (const auto& col : csv.columns) {
    const auto v = csv.column(col);
    ASSERT_EQ(v.size(), rows) << col;
    for (const double x : v) EXPECT_TRUE(std::isfinite(x)) << col;
  }
  const auto di = csv.column("di");
  EXPECT_GT(di.back(), 0.3);   // a biconcave disc: DI ~ 0.5 at rest; it must neither collapse nor explode
  EXPECT_LT(di.back(), 0.8);
}

TEST(ShearCli, QuickRunGivesAFlowModeAndTheGroups) {
  // 40 samples of 0.2 ms = 8 ms (960 steps, ~0.17 Jeffery period): every stage and output, not a whole flip.
  const auto dir = write_variant("shear", "quick", "vtk_every_s = 0.01", "vtk_every_s = 0.004");
  const auto out = dir / "out";
  std::string log;
  ASSERT_EQ(run("run --quiet --quick " + dir.string() + " --output " + out.string(), &log), 0) << log;
  expect_finite_series(out, 40);
  const auto s = summary(out);
  const auto r = s["results"];
  // 8 ms cannot show the mode (2 Jeffery periods, 97 ms): the case's checks are skipped and say so, never passed.
  // The membrane solve's check is decided: every one of the 480 npFEM steps converged.
  EXPECT_EQ(s["checks_skipped"].get<int>(), 2) << s["checks"].dump();
  EXPECT_EQ(s["checks_failed"].get<int>(), 0) << s["checks"].dump();
  EXPECT_NE(log.find("skipped flow mode tumbling"), std::string::npos) << log;
  EXPECT_NEAR(r["shear_rate_1_s"].get<double>(), 400.0, 1e-12);
  EXPECT_NEAR(r["ca"].get<double>(), 1.025e-3 * 400.0 * 3.91e-6 / 1.0e-4, 1e-12);   // mu gamma a / k_s
  EXPECT_NEAR(r["reynolds"].get<double>(), 400.0 * 24e-6 * 24e-6 / 1e-6, 1e-12);
  EXPECT_NEAR(r["jeffery_period_s"].get<double>(), 2.0 * std::numbers::pi * (0.37 + 1.0 / 0.37) / 400.0, 1e-12);
  for (const char* key : {"mean_inclination_rad", "tank_treading_frequency_hz", "di_mean", "di_gyration_mean", "period_s",
                          "particle_reynolds"}) {
    EXPECT_TRUE(r.contains(key)) << key;
  }
  // The cell's Stokes number from the membrane's (scaled) mass: m gamma / (6 pi mu a), m = 1125 kg/m^3 x mass factor x
  // the mesh's volume, which for 258 vertices is within 5 % of the exact Evans-Fung 94.1 um^3.
  const auto& n = s["numerics"];
  const double mass_kg = 1125.0 * n["membrane_mass_factor"].get<double>() * 94.1e-18;
  EXPECT_NEAR(n["cell_stokes_number"].get<double>() / (mass_kg * 400.0 / (6.0 * std::numbers::pi * 1.025e-3 * 3.91e-6)),
              1.0, 0.05);
  // Above 0.05 the run warns that the membrane's numerical mass changes the motion (measured at 10.7 mPa s).
  EXPECT_EQ(log.find("cell Stokes number") != std::string::npos, n["cell_stokes_number"].get<double>() > 0.05) << log;
  // The stiff disc starts parallel to the plates and must start turning with the flow (clockwise: angle < 0).
  const auto incl = hs::common::read_csv(out / "timeseries.csv").column("inclination_rad");
  EXPECT_LT(incl.back(), -0.05);
  EXPECT_TRUE(fs::exists(out / "membrane.pvd"));
  EXPECT_TRUE(fs::exists(out / "fields.pvd"));
}

TEST(ShearCli, HeavyMembraneInTheStokesAnalogueWarns) {
  // The 10.7 mPa s analogue at Ca 2.04 with the plasma's viscosity runs at St 0.18 (mass factor 100, 1274 1/s): --quick
  // is enough to be warned. With [flow] stokes_analogue (the shipped case) every viscosity is doubled: St / 4, no warning.
  const auto heavy = write_variant("shear/fischer-korzeniewski/medium-10.7", "stokes", "stokes_analogue = true",
                                   "stokes_analogue = false");
  std::string log;
  ASSERT_EQ(run("run --quiet --quick " + heavy.string() + " --output " + (heavy / "out").string(), &log), 0) << log;
  const double heavy_stokes = summary(heavy / "out")["numerics"]["cell_stokes_number"].get<double>();
  EXPECT_GT(heavy_stokes, 0.05);
  EXPECT_NE(log.find("cell Stokes number"), std::string::npos) << log;
  const auto analogue = write_variant("shear/fischer-korzeniewski/medium-10.7", "analogue", "stokes_analogue = true",
                                      "stokes_analogue = true");
  ASSERT_EQ(run("run --quiet --quick " + analogue.string() + " --output " + (analogue / "out").string(), &log), 0) << log;
  const auto n = summary(analogue / "out")["numerics"];
  EXPECT_EQ(n["analogue_viscosity_factor"].get<double>(), 2.0);
  EXPECT_NEAR(n["cell_stokes_number"].get<double>(), heavy_stokes / 4.0, 1e-9 * heavy_stokes);   // St ~ 1 / factor^2
  EXPECT_EQ(log.find("cell Stokes number"), std::string::npos) << log;
}

TEST(MigrationCli, QuickRunMovesTowardTheCentrelineWithoutTurningBack) {
  // 40 samples of 1 ms = 40 ms (~12 s of one core): past the 0.6 ms spin-up the cell released at y0 = 0.3 H moves
  // toward the centreline (measured 0.30 -> 0.42 H; it reaches it after ~0.15 s). The case's [check] asserts that the
  // offset shrank and never grew back by more than the centroid's 0.1 dx jitter (plate_cell_checks.cpp).
  const auto dir = write_variant("migration", "quick", "vtk_every_s = 0.02", "vtk_every_s = 0.02");
  const auto out = dir / "out";
  std::string log;
  ASSERT_EQ(run("run --quiet --quick " + dir.string() + " --output " + out.string(), &log), 0) << log;
  expect_finite_series(out, 40);
  const auto s = summary(out);
  EXPECT_EQ(s["checks"].size(), 3U) << s.dump();   // the case's two and the membrane solve's (every cell case)
  EXPECT_TRUE(s["passed"].get<bool>()) << s["checks"].dump();
  const auto r = s["results"];
  EXPECT_NEAR(r["reynolds"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(r["u_max_m_s"].get<double>(), 0.1 * 1e-6 / 24e-6, 1e-15);
  for (const char* key : {"final_y_over_h", "migration_speed_m_s", "lateral_position", "half_offset_time_s", "ca", "ca_initial"}) {
    EXPECT_TRUE(r.contains(key)) << key;
  }
  const auto vx = hs::common::read_csv(out / "timeseries.csv").column("velocity_x_m_s");
  EXPECT_GT(vx.back(), 0.0);   // carried downstream by the flow
}

/// Runs `folder` for `whole` seconds at once and for `part` then --resume to `whole`; the two series must agree bit for
/// bit. `part` must end on a sample (the stopped run writes its last sample there, and the resumed one samples on).
void expect_resume_repeats_the_series(const std::string& folder, const std::string& cap, const std::string& part_s,
                                      const std::string& whole_s) {
  const auto whole = write_variant(folder, "resume_whole", cap, "max_time_s = " + whole_s + " ");
  ASSERT_EQ(run("run --quiet " + whole.string() + " --output " + (whole / "out").string()), 0);
  const auto part = write_variant(folder, "resume_part", cap, "max_time_s = " + part_s + " ");
  const auto out = part / "out";
  ASSERT_EQ(run("run --quiet " + part.string() + " --output " + out.string()), 0);
  const auto rest = write_variant(folder, "resume_rest", cap, "max_time_s = " + whole_s + " ");
  std::string log;
  ASSERT_EQ(run("run --quiet " + rest.string() + " --output " + out.string() + " --resume", &log), 0) << log;
  const auto a = hs::common::read_csv(whole / "out" / "timeseries.csv");
  const auto b = hs::common::read_csv(out / "timeseries.csv");
  for (const auto& col : a.columns) {
    const auto x = a.column(col);
    const auto y = b.column(col);
    ASSERT_EQ(x.size(), y.size()) << col;
    for (std::size_t k = 0; k < x.size(); ++k) EXPECT_EQ(y[k], x[k]) << col << " row " << k;
  }
}

TEST(ShearCli, StoppedAndResumedRunGivesTheUninterruptedTimeSeries) {
  // The shared checkpoint (populations, force field, membrane, markers, samples) must continue bit for bit.
  expect_resume_repeats_the_series("shear", "max_jeffery_periods = 2.5 ", "0.0008", "0.0016");   // samples: 24 steps
}

TEST(ShearCli, ReactionCouplingResumesBitForBit) {
  // membrane_force = "ibm_reaction": the reaction summed since the last membrane step is in the checkpoint too.
  // Samples every 38 steps of 5.344 us: 4 and 8 of them.
  expect_resume_repeats_the_series("shear/tank-treading-reaction", "max_jeffery_periods = 4 ", "0.00081", "0.00162");
}

TEST(ShearCli, CytoplasmResumesBitForBit) {
  // The cytoplasm's nodes are a function of the markers (restored), marked at each membrane interval's start, and
  // checkpoints fall on those starts. Samples every 118 steps of 1.7083 us: 4 and 8 of them.
  expect_resume_repeats_the_series("shear/tank-treading-cytoplasm", "max_jeffery_periods = 4 ", "0.000806", "0.0016126");
}

}  // namespace
