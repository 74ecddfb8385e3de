// SPDX-License-Identifier: MIT
// The stenosis study's statistics and checks.
#include "study/stenosis_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/batch_means.hpp"

namespace hs::study {
namespace {

/// summary.json results.study_layout.
struct Layout {
  int bins = 0;
  std::vector<double> x_m;
  std::vector<double> radius_m;
  std::vector<double> fluid_m3;
  double throat_x_m = 0.0;
  double constriction_length_m = 0.0;
  std::vector<double> upstream;
  std::vector<double> downstream;
  std::vector<std::string> inlets;
  bool fluid_stores = false;
  double dt_s = 0.0;

  explicit Layout(const nlohmann::json& j)
      : bins(j.at("x_bins").get<int>()), x_m(j.at("bin_centres_m").get<std::vector<double>>()),
        radius_m(j.at("wall_radius_m").get<std::vector<double>>()), fluid_m3(j.at("bin_fluid_m3").get<std::vector<double>>()),
        throat_x_m(j.at("throat_x_m").get<double>()), constriction_length_m(j.at("constriction_length_m").get<double>()),
        upstream(j.at("upstream_window_m").get<std::vector<double>>()),
        downstream(j.at("downstream_window_m").get<std::vector<double>>()),
        inlets(j.at("inlets").get<std::vector<std::string>>()), fluid_stores(j.at("fluid_stores").get<bool>()),
        dt_s(j.at("dt_s").get<double>()) {}
};

std::string col(int bin, const char* what) { return fmt::format("x{}_{}", bin, what); }

/// Sum over the bins whose centre lies in [w0, w1] of column `what` in a row.
RowFn window_sum(const Layout& l, const Columns& cols, const std::vector<double>& w, const char* what) {
  std::vector<std::size_t> at;
  for (int i = 0; i < l.bins; ++i) {
    if (l.x_m[static_cast<std::size_t>(i)] >= w[0] && l.x_m[static_cast<std::size_t>(i)] <= w[1]) at.push_back(cols.at(col(i, what)));
  }
  return [at](const std::vector<double>& r) {
    double s = 0.0;
    for (const std::size_t c : at) s += r[c];
    return s;
  };
}

/// Window sum of column `c` over rows [start, end).
double total(const Rows& rows, std::size_t start, std::size_t c) {
  double s = 0.0;
  for (std::size_t k = start; k < rows.size(); ++k) s += rows[k][c];
  return s;
}

}  // namespace

nlohmann::json stenosis_statistics(const nlohmann::json& layout, const std::vector<std::string>& columns, const Rows& rows) {
  const Layout l(layout);
  const Columns cols(columns);
  if (rows.size() < static_cast<std::size_t>(2 * kStudyBatches)) return {{"too_short", true}};
  std::vector<std::string> monitored{"cells_present", "mean_di"};
  std::vector<std::string> outlets;
  for (const auto& [name, index] : cols.all()) {
    const std::string suffix = "_fluid_flux_m3_s";
    if (name.size() < suffix.size() || name.substr(name.size() - suffix.size()) != suffix) continue;
    const std::string n = name.substr(0, name.size() - suffix.size());
    if (std::find(l.inlets.begin(), l.inlets.end(), n) != l.inlets.end()) continue;
    outlets.push_back(n);
    monitored.insert(monitored.end(), {n + "_fluid_flux_m3_s", n + "_rbc_flux_m3_s"});
  }
  nlohmann::json j;
  j["steady"] = steady_block(cols, rows, monitored, l.dt_s);
  const std::size_t start = std::min(j["steady"]["start_step"].get<std::size_t>(), rows.size() - 2 * kStudyBatches);
  j["window_start_step"] = start;
  j["window_start_time_s"] = static_cast<double>(start) * l.dt_s;
  j["batches"] = kStudyBatches;
  j["conservation"] = conservation_block(cols, rows, start, l.inlets, l.fluid_stores, l.dt_s);
  // The blood flow rate in (plasma + cells) over the window, for the Poiseuille wall-shear estimate.
  double q_blood = 0.0;
  for (const auto& n : l.inlets) {
    q_blood += (total(rows, start, cols.at(n + "_fluid_flux_m3_s")) + total(rows, start, cols.at(n + "_rbc_flux_m3_s"))) /
               static_cast<double>(rows.size() - start);
  }
  nlohmann::json profile = nlohmann::json::array();
  nlohmann::json best;
  for (int i = 0; i < l.bins; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const std::size_t cells = cols.at(col(i, "cells"));
    const std::size_t di = cols.at(col(i, "di_sum"));
    const std::size_t di_sq = cols.at(col(i, "di_sq_sum"));
    const std::size_t ux = cols.at(col(i, "ux_sum"));
    const double n = total(rows, start, cells);
    const auto di_mean = batch_ratio(rows, start, [di](const std::vector<double>& r) { return r[di]; },
                                     [cells](const std::vector<double>& r) { return r[cells]; });
    const double mean_sq = n > 0.0 ? total(rows, start, di_sq) / n : 0.0;
    const double sd = std::sqrt(std::max(0.0, mean_sq - di_mean.mean * di_mean.mean));
    const auto ux_mean = batch_ratio(rows, start, [ux](const std::vector<double>& r) { return r[ux]; },
                                     [cells](const std::vector<double>& r) { return r[cells]; });
    std::vector<double> ht;
    for (const auto& r : rows) ht.push_back(r[cols.at(col(i, "rbc_m3"))] / l.fluid_m3[u]);
    const auto ht_mean = hs::common::batch_means(ht, kStudyBatches, start);
    const auto shear = hs::common::batch_means(cols.series(rows, col(i, "wall_shear_1_s")), kStudyBatches, start);
    const double r_w = l.radius_m[u];
    nlohmann::json b{{"x_m", l.x_m[u]}, {"wall_radius_m", r_w}, {"cell_samples", n}, {"di_mean", di_mean.mean},
                     {"di_mean_se", di_mean.standard_error}, {"di_sd", sd}, {"hematocrit", ht_mean.mean},
                     {"hematocrit_se", ht_mean.standard_error}, {"ux_mean_m_s", ux_mean.mean}, {"ux_mean_se", ux_mean.standard_error},
                     {"wall_shear_1_s", shear.mean}, {"wall_shear_poiseuille_1_s", 4.0 * q_blood / (std::numbers::pi * r_w * r_w * r_w)},
                     {"outside_di_share", n > 0.0 ? total(rows, start, cols.at(col(i, "outside_di"))) / n : 0.0},
                     {"outside_any_share", n > 0.0 ? total(rows, start, cols.at(col(i, "outside_any"))) / n : 0.0}};
    if (n >= kMinBinSamples && (best.is_null() || di_mean.mean > best["value"].get<double>())) {
      best = {{"value", di_mean.mean}, {"se", di_mean.standard_error}, {"sd", sd}, {"x_m", l.x_m[u]},
              {"from_throat_m", l.x_m[u] - l.throat_x_m},
              {"from_throat_constriction_lengths", (l.x_m[u] - l.throat_x_m) / l.constriction_length_m}};
    }
    profile.push_back(b);
  }
  if (best.is_null()) {   // no bin has enough samples (a --quick run): the maximum over the bins holding any, flagged
    for (const auto& b : profile) {
      if (b["cell_samples"].get<double>() > 0.0 && (best.is_null() || b["di_mean"].get<double>() > best["value"].get<double>())) {
        best = {{"value", b["di_mean"]}, {"se", b["di_mean_se"]}, {"sd", b["di_sd"]}, {"x_m", b["x_m"]},
                {"from_throat_m", b["x_m"].get<double>() - l.throat_x_m},
                {"from_throat_constriction_lengths", (b["x_m"].get<double>() - l.throat_x_m) / l.constriction_length_m}};
      }
    }
    if (!best.is_null()) best["enough_samples"] = false;
  } else {
    best["enough_samples"] = true;
  }
  j["profile"] = profile;
  j["di_max"] = best;
  j["blood_flow_rate_m3_s"] = q_blood;
  for (const auto& [key, w] : {std::pair{"di_upstream", l.upstream}, std::pair{"di_downstream", l.downstream}}) {
    const auto m = batch_ratio(rows, start, window_sum(l, cols, w, "di_sum"), window_sum(l, cols, w, "cells"));
    const auto out = batch_ratio(rows, start, window_sum(l, cols, w, "outside_any"), window_sum(l, cols, w, "cells"));
    j[key] = {{"mean", m.mean}, {"se", m.standard_error}, {"window_m", w}, {"outside_any_share", out.mean}};
  }
  return j;
}

void check_stenosis_study(const nlohmann::json& s, bool quick, const std::string& prefix, hs::common::CheckList& checks) {
  if (s.contains("too_short")) {
    checks.expect(prefix + "enough samples for the statistics", false, fmt::format("fewer than {} steps", 2 * kStudyBatches));
    return;
  }
  check_cell_count(s["conservation"], prefix, checks);
  if (quick) {
    checks.skip(prefix + "steady state, steady window, fluid balance", "--quick: the tube has not filled yet");
    return;
  }
  check_steady_block(s["steady"], prefix, checks);
  const double balance = s["conservation"]["fluid_balance_pct"].get<double>();
  checks.expect(prefix + "fluid in = fluid out over the window", std::abs(balance) <= 0.1,
                fmt::format("{:+.4f}% (band +-0.1%)", balance));
  checks.expect(prefix + "a maximum of <DI>(x) over bins with enough cells",
                !s["di_max"].is_null() && s["di_max"]["enough_samples"].get<bool>(),
                fmt::format("bins need >= {:.0f} cell samples", kMinBinSamples));
}

}  // namespace hs::study
