// SPDX-License-Identifier: MIT
// The study's statistics and checks on synthetic series with known answers: S_H of a linear and a uniform profile,
// flux fractions, DI_av; each check fails when its condition is broken (a ramp, a lost cell, a fluid leak).
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "study/bifurcation_statistics.hpp"

namespace hs::study {
namespace {

constexpr int kBins = 10;
constexpr int kDiBins = 4;   // over [0.4, 0.6]: bins of 0.05

struct Synthetic {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  nlohmann::json layout;
};

/// `steps` rows: inlet 1.0 in, outlet `q_outlet` and daughter `q_daughter` out (fluid), cells 100 in, 40 + 50 out,
/// 10 present (+ `ramp` x step), daughter profile H = 0.2 (1 + 0.5 (2w - 1)), outlet uniform 0.2, every cell DI 0.52.
Synthetic make(int steps, double q_outlet, double q_daughter, double ramp, double daughter_out) {
  Synthetic s;
  std::vector<double> fluid(kBins, 1e-16);
  s.layout = {{"branches", {"parent", "outlet", "daughter"}}, {"profile_bins", kBins}, {"cut_bin_fluid_m3", {fluid, fluid}},
              {"di_range", {0.4, 0.6}}, {"di_bins", kDiBins}, {"di_threshold", 0.5}, {"inlets", {"inlet"}},
              {"fluid_stores", false}, {"dt_s", 1e-4}};
  s.columns = {"time_s", "cells_present", "plasma_volume_m3"};
  for (const char* o : {"daughter", "inlet", "outlet"}) {
    for (const char* w : {"_cells_in", "_cells_out", "_rbc_flux_m3_s", "_fluid_flux_m3_s"}) s.columns.push_back(std::string(o) + w);
  }
  for (const char* b : {"outlet", "daughter"}) {
    s.columns.push_back(std::string(b) + "_cut_ht");
    for (int i = 0; i < kBins; ++i) s.columns.push_back(fmt::format("{}_cut_rbc_m3_bin_{}", b, i));
  }
  for (const char* b : {"parent", "outlet", "daughter"}) {
    for (const char* w : {"_cells", "_di_sum", "_di_below", "_di_above"}) s.columns.push_back(std::string(b) + w);
    for (int i = 0; i < kDiBins; ++i) s.columns.push_back(fmt::format("{}_di_bin_{}", b, i));
  }
  for (int k = 0; k < steps; ++k) {
    std::vector<double> r{k * 1e-4, 10.0 + ramp * k, 0.0};
    r.insert(r.end(), {0.0, daughter_out, 0.1 * q_daughter, 0.9 * q_daughter});     // daughter
    r.insert(r.end(), {100.0, 0.0, 0.1, 0.9});                                      // inlet: blood 1.0, RBC 0.1
    r.insert(r.end(), {0.0, 40.0, 0.1 * q_outlet, 0.9 * q_outlet});                 // outlet
    r.push_back(0.2);
    for (int i = 0; i < kBins; ++i) r.push_back(0.2 * 1e-16);
    r.push_back(0.2);
    for (int i = 0; i < kBins; ++i) r.push_back(0.2 * (1.0 + 0.5 * (2.0 * (i + 0.5) / kBins - 1.0)) * 1e-16);
    for (int b = 0; b < 3; ++b) r.insert(r.end(), {2.0, 1.04, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0});   // DI 0.52: bin 2
    s.rows.push_back(r);
  }
  return s;
}

int failed_checks(const Synthetic& s, bool quick = false) {
  hs::common::CheckList checks;
  check_bifurcation_study(bifurcation_statistics(s.layout, s.columns, s.rows), quick, "", checks);
  return checks.exit_code();
}

TEST(BifurcationStatistics, KnownProfilesFluxesAndDeformation) {
  const Synthetic s = make(400, 0.6, 0.4, 0.0, 50.0);
  const auto j = bifurcation_statistics(s.layout, s.columns, s.rows);
  // Noiseless series: every value exact to round-off (1e-12 relative).
  EXPECT_NEAR(j["branches"]["daughter"]["s_h"].get<double>(), 0.5, 1e-12);   // linear, even n: |a|
  EXPECT_NEAR(j["branches"]["outlet"]["s_h"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["branches"]["daughter"]["hematocrit"][0].get<double>(), 0.2 * (1.0 - 0.45), 1e-12);
  EXPECT_NEAR(j["branches"]["daughter"]["blood_flux_fraction"].get<double>(), 0.4, 1e-12);
  EXPECT_NEAR(j["branches"]["outlet"]["rbc_flux_fraction"].get<double>(), 0.6, 1e-12);
  EXPECT_NEAR(j["di"]["all"]["di_av"].get<double>(), 0.52, 1e-12);
  // 2 cells per branch per step over the window (its start is MSER's on flat series: wherever round-off puts it).
  EXPECT_EQ(j["di"]["all"]["cell_samples"].get<long>(), 3 * 2 * (400 - j["window_start_step"].get<long>()));
  EXPECT_DOUBLE_EQ(j["di"]["all"]["fraction_above"].get<double>(), 1.0);   // 0.52 > 0.5
  EXPECT_NEAR(j["conservation"]["fluid_balance_pct"].get<double>(), 0.0, 1e-10);
  EXPECT_TRUE(j["steady"]["all_found"].get<bool>());
  EXPECT_EQ(failed_checks(s), 0);
}

TEST(BifurcationStatistics, EachCheckCanFail) {
  EXPECT_EQ(failed_checks(make(400, 0.6, 0.4, 0.05, 50.0)), 1);   // cells_present ramps: not steady (nor does the count close)
  EXPECT_EQ(failed_checks(make(400, 0.6, 0.4, 0.0, 51.0)), 1);    // a cell counted out twice: 100 != 91 + 10
  EXPECT_EQ(failed_checks(make(400, 0.6, 0.3, 0.0, 50.0)), 1);    // 10% of the fluid lost
  EXPECT_EQ(failed_checks(make(400, 0.6, 0.3, 0.0, 50.0), true), 0);   // --quick skips the fluid balance
  EXPECT_EQ(failed_checks(make(400, 0.6, 0.4, 0.0, 51.0), true), 1);   // but never the cell count
  EXPECT_EQ(failed_checks(make(5, 0.6, 0.4, 0.0, 50.0)), 1);      // too few steps for any statistics
}

}  // namespace
}  // namespace hs::study
