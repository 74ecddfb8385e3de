// SPDX-License-Identifier: MIT
// Checkpoint/restart of the tube-pries case: a run stopped after K steps and resumed gives the uninterrupted
// run's time series and summary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "unresolved/cases/short_tube_case.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/io/checkpoint.hpp"
#include "common/io/csv_writer.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace {

namespace fs = std::filesystem;
using hs::unresolved::TubePriesSample;

/// A short 30 um tube at Ht_c = 0.30 (68 spheres; 30 contact springs at the stop, so the springs' restart is
/// exercised), with the Haberman-Sayre wall correction, a lift (its per-sphere column) and the suspension viscosity
/// (its factor field) on; `steps` CFD steps of 0.2 ms (125 DEM steps each).
std::string restart_case(int steps) {
  return hs::test::short_tube_case("0.30",
                                   "drag = \"schiller_naumann\"\nlift = \"saffman_mei\"\nsuspension_viscosity = \"pries_bulk\"\n"
                                   "wall_correction = \"haberman_sayre\"\n",
                                   "125", std::to_string(2e-4 * steps));
}

hs::unresolved::TubePriesConfig config(int steps) {
  auto file = hs::common::ConfigFile::parse(restart_case(steps), "case.toml");
  (void)file->root().section("case").string("type");
  return hs::unresolved::parse_tube_pries(*file, false);
}

std::vector<TubePriesSample> run(int steps, const hs::unresolved::TubePriesRestart& restart, double* ht_d = nullptr) {
  std::vector<TubePriesSample> series;
  const auto r = hs::unresolved::simulate_tube_pries(config(steps), [&](const TubePriesSample& s) { series.push_back(s); }, restart);
  if (ht_d != nullptr) *ht_d = r.ht_d;
  return series;
}

TEST(TubePriesRestart, StoppedAndResumedRunFollowsTheUninterruptedOne) {
  constexpr int kAll = 20, kStop = 10;
  const fs::path dir = fs::temp_directory_path() / "hs_tube_pries_restart";
  fs::remove_all(dir);
  double ht_whole = 0.0, ht_resumed = 0.0;
  const auto whole = run(kAll, {}, &ht_whole);
  const auto first = run(kStop, {.dir = dir, .resume = false, .rank = 0});
  ASSERT_EQ(first.size(), static_cast<std::size_t>(kStop));
  const auto saved = hs::common::Checkpoint::read(dir, 0);
  const std::size_t springs = saved.integers("dem.contact_ids").size() / 2;
  EXPECT_GT(springs, 0u);
  std::printf("checkpoint at step %d: %zu spheres, %zu contact springs\n", kStop, saved.integers("dem.ids").size(), springs);
  const auto resumed = run(kAll, {.dir = dir, .resume = true, .rank = 0}, &ht_resumed);
  ASSERT_EQ(whole.size(), static_cast<std::size_t>(kAll));
  ASSERT_EQ(resumed.size(), whole.size());   // the saved samples are replayed, then the run goes on
  double worst = 0.0;
  for (std::size_t k = 0; k < whole.size(); ++k) {
    const double a[] = {whole[k].time_s, whole[k].q_blood_m3_s, whole[k].q_rbc_m3_s, whole[k].ht_d};
    const double b[] = {resumed[k].time_s, resumed[k].q_blood_m3_s, resumed[k].q_rbc_m3_s, resumed[k].ht_d};
    for (int v = 0; v < 4; ++v) {
      if (k < static_cast<std::size_t>(kStop)) {
        EXPECT_EQ(b[v], a[v]) << "sample " << k;   // same code, same inputs before the stop: bit for bit
      } else {
        worst = std::max(worst, std::abs(b[v] - a[v]) / std::abs(a[v]));
      }
    }
  }
  // After the restart the fluid, the coupling state and every particle column are restored exactly, but the DEM
  // re-sorts its particles when it rebuilds the neighbour list at the restart (dem_checkpoint.hpp), so the
  // per-cell sums of the void fraction, Ksl and the drag exchange are added in another order: round-off, 1e-16
  // per sum (measured 6.5e-16 after 10 steps), which contacts amplify over longer runs. 1e-10 relative: 1e5 above
  // the measured round-off, and the 10 significant digits timeseries.csv prints.
  EXPECT_LT(worst, 1e-10);
  EXPECT_NEAR(ht_resumed, ht_whole, 1e-10 * ht_whole);
  std::printf("resumed vs uninterrupted: max relative difference %.3e over steps %d-%d\n", worst, kStop + 1, kAll);
  fs::remove_all(dir);
}

TEST(TubePriesRestart, RunFolderResumeRewritesTheTimeSeries) {
  // The `hemoscale run CASE --output DIR --resume` path: RunContext reopens the folder, the case reads its
  // checkpoint, timeseries.csv gets the saved rows again, then the new ones.
  const fs::path out = fs::temp_directory_path() / "hs_tube_pries_resume_folder";
  fs::remove_all(out);
  for (const auto& [steps, resume] : {std::pair{2, false}, std::pair{4, true}}) {
    auto file = hs::common::ConfigFile::parse(restart_case(steps), "case.toml");
    (void)file->root().section("case").string("type");
    const hs::common::CaseRequest request{.case_dir = fs::temp_directory_path(), .config = file.get(), .output_dir = out,
                                          .resume = resume, .quiet = true, .quick = false};
    // 2 and 4 steps are far from a steady state: the case's own check fails (exit 1) and the outputs are written.
    ASSERT_EQ(hs::unresolved::run_tube_pries(request), 1);
  }
  const auto table = hs::common::read_csv(out / "timeseries.csv");
  const auto t = table.column("time_s");
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], 2e-4 * static_cast<double>(k + 1), 1e-12) << "row " << k;
  std::ifstream in(out / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(in)["numerics"]["cfd_steps"].get<long>(), 4);
  fs::remove_all(out);
}

TEST(TubePriesRestart, MissingCheckpointIsAConfigError) {
  const fs::path dir = fs::temp_directory_path() / "hs_tube_pries_no_checkpoint";
  fs::remove_all(dir);
  EXPECT_THROW((void)run(2, {.dir = dir, .resume = true, .rank = 0}), hs::common::ConfigError);
}

}  // namespace
