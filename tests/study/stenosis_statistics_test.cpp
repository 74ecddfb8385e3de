// SPDX-License-Identifier: MIT
// The stenosis study's statistics and checks on synthetic series with known answers: <DI>(x), its spread, Ht(x),
// the maximum and its place, the windows before and after the narrowing, the Poiseuille wall-shear estimate; the
// checks fail on a lost cell and on a fluid leak.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "study/stenosis_statistics.hpp"

namespace hs::study {
namespace {

constexpr int kBins = 4;            // x bins of 10 um: centres 5, 15, 25, 35 um; throat at 20 um
constexpr double kVolume = 1e-13;   // fluid volume of every bin, m^3
constexpr double kCell = 1e-16;     // RBC volume of one cell, m^3

struct Synthetic {
  std::vector<std::string> columns;
  Rows rows;
  nlohmann::json layout;
};

/// `steps` rows, steady: bin i holds 500 cells every step, half with DI d_i - 0.01 and half with d_i + 0.01
/// (d = 0.50, 0.51, 0.53, 0.52): mean d_i, spread 0.01; axial velocity 1 mm/s; wall shear 100 1/s; a tenth of
/// the cells outside validity. Inlet 1e-12 m^3/s of plasma and 1e-13 of cells; the outlet `leak` times that.
Synthetic make(int steps, double leak, double cells_out) {
  Synthetic s;
  s.layout = {{"x_bins", kBins}, {"bin_centres_m", {5e-6, 15e-6, 25e-6, 35e-6}}, {"wall_radius_m", {20e-6, 10e-6, 10e-6, 20e-6}},
              {"bin_fluid_m3", std::vector<double>(kBins, kVolume)}, {"throat_x_m", 20e-6}, {"constriction_length_m", 20e-6},
              {"upstream_window_m", {0.0, 10e-6}}, {"downstream_window_m", {30e-6, 40e-6}}, {"inlets", {"inlet"}},
              {"fluid_stores", false}, {"dt_s", 1e-3}};
  s.columns = {"time_s", "cells_present", "mean_di", "plasma_volume_m3"};
  for (const char* o : {"inlet", "outlet"}) {
    for (const char* w : {"_cells_in", "_cells_out", "_rbc_flux_m3_s", "_fluid_flux_m3_s"}) s.columns.push_back(std::string(o) + w);
  }
  for (int i = 0; i < kBins; ++i) {
    for (const char* w : {"cells", "di_sum", "di_sq_sum", "ux_sum", "rbc_m3", "outside_di", "outside_any", "wall_shear_1_s"}) {
      s.columns.push_back(fmt::format("x{}_{}", i, w));
    }
  }
  const double d[kBins] = {0.50, 0.51, 0.53, 0.52};
  for (int k = 0; k < steps; ++k) {
    std::vector<double> r{k * 1e-3, 2000.0, 0.515, 0.0};
    r.insert(r.end(), {3000.0, 0.0, 1e-13, 1e-12});
    r.insert(r.end(), {0.0, cells_out, 1e-13, leak * 1e-12});
    for (int i = 0; i < kBins; ++i) {
      const double lo = d[i] - 0.01;
      const double hi = d[i] + 0.01;
      r.insert(r.end(), {500.0, 250.0 * (lo + hi), 250.0 * (lo * lo + hi * hi), 500.0 * 1e-3, 500.0 * kCell, 50.0, 50.0, 100.0});
    }
    s.rows.push_back(r);
  }
  return s;
}

TEST(StenosisStatistics, ProfileMaximumAndWindows) {
  const Synthetic s = make(200, 1.0, 1000.0);
  const auto j = stenosis_statistics(s.layout, s.columns, s.rows);
  ASSERT_FALSE(j.contains("too_short"));
  const auto& p = j["profile"];
  ASSERT_EQ(p.size(), 4u);
  // Exact to round-off: the series are constant.
  EXPECT_NEAR(p[2]["di_mean"].get<double>(), 0.53, 1e-12);
  EXPECT_NEAR(p[2]["di_sd"].get<double>(), 0.01, 1e-7);   // sqrt(<DI^2> - <DI>^2): cancellation leaves ~1e-8
  EXPECT_NEAR(p[0]["hematocrit"].get<double>(), 500.0 * kCell / kVolume, 1e-12);
  EXPECT_NEAR(p[1]["ux_mean_m_s"].get<double>(), 1e-3, 1e-15);
  EXPECT_NEAR(p[3]["wall_shear_1_s"].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(p[3]["outside_any_share"].get<double>(), 0.1, 1e-12);
  // Poiseuille: 4 Q / (pi r^3) with Q the blood inflow 1.1e-12 m^3/s.
  EXPECT_NEAR(p[1]["wall_shear_poiseuille_1_s"].get<double>() / (4.0 * 1.1e-12 / (std::numbers::pi * 1e-15)), 1.0, 1e-12);
  EXPECT_NEAR(j["di_max"]["value"].get<double>(), 0.53, 1e-12);
  EXPECT_NEAR(j["di_max"]["x_m"].get<double>(), 25e-6, 1e-18);
  EXPECT_NEAR(j["di_max"]["from_throat_m"].get<double>(), 5e-6, 1e-18);
  EXPECT_TRUE(j["di_max"]["enough_samples"].get<bool>());
  EXPECT_NEAR(j["di_upstream"]["mean"].get<double>(), 0.50, 1e-12);
  EXPECT_NEAR(j["di_downstream"]["mean"].get<double>(), 0.52, 1e-12);
  hs::common::CheckList checks;
  check_stenosis_study(j, false, "", checks);
  EXPECT_EQ(checks.failed(), 0);
}

TEST(StenosisStatistics, LostCellAndLeakFail) {
  for (const auto& [leak, out, what] : {std::tuple{1.01, 1000.0, "fluid"}, std::tuple{1.0, 999.0, "cells"}}) {
    const Synthetic s = make(200, leak, out);
    hs::common::CheckList checks;
    check_stenosis_study(stenosis_statistics(s.layout, s.columns, s.rows), false, "", checks);
    EXPECT_EQ(checks.failed(), 1) << what;
  }
}

}  // namespace
}  // namespace hs::study
