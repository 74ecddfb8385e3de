// SPDX-License-Identifier: MIT
// The bifurcation study's statistics and checks.
#include "study/bifurcation_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "common/batch_means.hpp"
#include "analysis/cut_profile.hpp"
#include "analysis/histogram.hpp"
#include "analysis/skewness_index.hpp"
#include "analysis/steady_state.hpp"
#include "study/series_statistics.hpp"

namespace hs::study {
namespace {

/// summary.json results.study_layout.
struct Layout {
  std::vector<std::string> branches;              // parent, daughter 0, daughter 1
  int profile_bins = 0;
  std::vector<std::vector<double>> bin_fluid_m3;  // per daughter
  double di_lo = 0.0;
  double di_hi = 1.0;
  int di_bins = 1;
  double di_threshold = 0.5;
  std::vector<std::string> inlets;
  bool fluid_stores = false;
  double dt_s = 0.0;

  explicit Layout(const nlohmann::json& j)
      : branches(j.at("branches").get<std::vector<std::string>>()), profile_bins(j.at("profile_bins").get<int>()),
        bin_fluid_m3(j.at("cut_bin_fluid_m3").get<std::vector<std::vector<double>>>()), di_lo(j.at("di_range")[0].get<double>()),
        di_hi(j.at("di_range")[1].get<double>()), di_bins(j.at("di_bins").get<int>()), di_threshold(j.at("di_threshold").get<double>()),
        inlets(j.at("inlets").get<std::vector<std::string>>()), fluid_stores(j.at("fluid_stores").get<bool>()),
        dt_s(j.at("dt_s").get<double>()) {}
};

}  // namespace

namespace {

/// The profile across daughter `b`'s cut, S_H and the flux fractions over rows [start, end).
nlohmann::json branch_block(const Layout& info, int b, const Columns& cols, const Rows& rows, std::size_t start) {
  const std::string& name = info.branches[static_cast<std::size_t>(b)];
  const auto bins = static_cast<std::size_t>(info.profile_bins);
  const auto& fluid_m3 = info.bin_fluid_m3[static_cast<std::size_t>(b - 1)];
  Rows profile;   // H per bin at every step (batch_means starts at `start`)
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < bins; ++i) at.push_back(cols.at(fmt::format("{}_cut_rbc_m3_bin_{}", name, i)));
  for (const auto& r : rows) {
    std::vector<double> v(bins);
    for (std::size_t i = 0; i < bins; ++i) v[i] = r[at[i]];
    profile.push_back(hs::analysis::hematocrit_profile(v, fluid_m3));
  }
  const auto per_bin = hs::common::batch_means(profile, kStudyBatches, start);
  std::vector<double> w;
  std::vector<double> mean;
  std::vector<double> se;
  for (std::size_t i = 0; i < bins; ++i) {
    w.push_back((static_cast<double>(i) + 0.5) / static_cast<double>(bins));
    mean.push_back(per_bin[i].mean);
    se.push_back(per_bin[i].standard_error);
  }
  // S_H of each batch's mean profile: its spread gives S_H's standard error.
  const std::size_t len = (rows.size() - start) / kStudyBatches;
  const std::size_t off = rows.size() - len * kStudyBatches;
  std::vector<double> s_batches;
  for (int k = 0; k < kStudyBatches; ++k) {
    std::vector<double> h(bins, 0.0);
    for (std::size_t i = 0; i < len; ++i) {
      for (std::size_t j = 0; j < bins; ++j) h[j] += profile[off + static_cast<std::size_t>(k) * len + i][j] / static_cast<double>(len);
    }
    s_batches.push_back(hs::analysis::skewness_index(h));
  }
  nlohmann::json j{{"w", w}, {"hematocrit", mean}, {"hematocrit_se", se}, {"s_h", hs::analysis::skewness_index(mean)},
                   {"s_h_se", hs::common::batch_means(s_batches, kStudyBatches).standard_error},
                   {"s_h_batch_mean", hs::common::batch_means(s_batches, kStudyBatches).mean}};
  const auto cut = hs::common::batch_means(cols.series(rows, name + "_cut_ht"), kStudyBatches, start);
  j["cut_hematocrit"] = cut.mean;
  j["cut_hematocrit_se"] = cut.standard_error;
  if (!cols.has(name + "_fluid_flux_m3_s") || info.inlets.empty()) return j;   // no outlet named as the branch
  const std::size_t rbc = cols.at(name + "_rbc_flux_m3_s");
  const std::size_t fluid = cols.at(name + "_fluid_flux_m3_s");
  std::vector<std::pair<std::size_t, std::size_t>> in;
  for (const auto& n : info.inlets) in.emplace_back(cols.at(n + "_rbc_flux_m3_s"), cols.at(n + "_fluid_flux_m3_s"));
  const RowFn in_rbc = [in](const std::vector<double>& r) { double s = 0.0; for (const auto& [a, f] : in) s += r[a]; return s; };
  const RowFn in_blood = [in](const std::vector<double>& r) { double s = 0.0; for (const auto& [a, f] : in) s += r[a] + r[f]; return s; };
  const auto blood = batch_ratio(rows, start, [rbc, fluid](const std::vector<double>& r) { return r[rbc] + r[fluid]; }, in_blood);
  const auto cells = batch_ratio(rows, start, [rbc](const std::vector<double>& r) { return r[rbc]; }, in_rbc);
  j["blood_flux_fraction"] = blood.mean;
  j["blood_flux_fraction_se"] = blood.standard_error;
  j["rbc_flux_fraction"] = cells.mean;
  j["rbc_flux_fraction_se"] = cells.standard_error;
  j["cells_out"] = rows.back()[cols.at(name + "_cells_out")];
  return j;
}

/// DI histogram of one branch (or of all, `names` holding the three) summed over the window's samples.
nlohmann::json di_block(const Layout& spec, const std::vector<std::string>& names, const Columns& cols,
                        const Rows& rows, std::size_t start) {
  hs::analysis::UniformHistogram h(spec.di_lo, spec.di_hi, spec.di_bins);
  double below = 0.0;
  double above = 0.0;
  for (std::size_t s = start; s < rows.size(); ++s) {
    for (const auto& n : names) {
      for (int i = 0; i < spec.di_bins; ++i) {
        h.add(h.bin_centre(i), static_cast<std::int64_t>(rows[s][cols.at(fmt::format("{}_di_bin_{}", n, i))]));
      }
      below += rows[s][cols.at(n + "_di_below")];
      above += rows[s][cols.at(n + "_di_above")];
    }
  }
  h.add(spec.di_lo - 1.0, static_cast<std::int64_t>(below));
  h.add(spec.di_hi + 1.0, static_cast<std::int64_t>(above));
  const RowFn sum = [&cols, names](const std::vector<double>& r) { double x = 0.0; for (const auto& n : names) x += r[cols.at(n + "_di_sum")]; return x; };
  const RowFn cells = [&cols, names](const std::vector<double>& r) { double x = 0.0; for (const auto& n : names) x += r[cols.at(n + "_cells")]; return x; };
  const auto di_av = batch_ratio(rows, start, sum, cells);
  return {{"counts", h.counts()}, {"below", h.below()}, {"above", h.above()}, {"cell_samples", h.total()},
          {"di_av", di_av.mean}, {"di_av_se", di_av.standard_error}, {"fraction_above", h.fraction_above(spec.di_threshold)}};
}

}  // namespace

nlohmann::json bifurcation_statistics(const nlohmann::json& layout, const std::vector<std::string>& columns, const Rows& rows) {
  const Layout info(layout);
  const Columns cols(columns);
  if (rows.size() < static_cast<std::size_t>(2 * kStudyBatches)) return {{"too_short", true}};
  std::vector<std::string> monitored{"cells_present"};
  for (int b = 1; b <= 2; ++b) {
    const std::string& n = info.branches[static_cast<std::size_t>(b)];
    monitored.push_back(n + "_cut_ht");
    if (cols.has(n + "_fluid_flux_m3_s")) monitored.insert(monitored.end(), {n + "_fluid_flux_m3_s", n + "_rbc_flux_m3_s"});
  }
  nlohmann::json j;
  j["steady"] = steady_block(cols, rows, monitored, info.dt_s);
  // The window: from the latest settled start, keeping at least 2 batches' worth (a --quick run has not settled).
  const std::size_t start = std::min(j["steady"]["start_step"].get<std::size_t>(), rows.size() - 2 * kStudyBatches);
  j["window_start_step"] = start;
  j["window_start_time_s"] = static_cast<double>(start) * info.dt_s;
  j["batches"] = kStudyBatches;
  for (int b = 1; b <= 2; ++b) {
    j["branches"][info.branches[static_cast<std::size_t>(b)]] = branch_block(info, b, cols, rows, start);
  }
  for (const auto& br : info.branches) j["di"][br] = di_block(info, {br}, cols, rows, start);
  j["di"]["all"] = di_block(info, info.branches, cols, rows, start);
  j["di"]["range"] = {info.di_lo, info.di_hi};
  j["di"]["bins"] = info.di_bins;
  j["di"]["threshold"] = info.di_threshold;
  std::vector<double> di_centres;
  for (int i = 0; i < info.di_bins; ++i) di_centres.push_back(info.di_lo + (i + 0.5) * (info.di_hi - info.di_lo) / info.di_bins);
  j["di"]["bin_centres"] = di_centres;
  j["conservation"] = conservation_block(cols, rows, start, info.inlets, info.fluid_stores, info.dt_s);
  return j;
}

void check_bifurcation_study(const nlohmann::json& s, bool quick, const std::string& prefix, hs::common::CheckList& checks) {
  if (s.contains("too_short")) {
    checks.expect(prefix + "enough samples for the statistics", false, fmt::format("fewer than {} steps", 2 * kStudyBatches));
    return;
  }
  check_cell_count(s["conservation"], prefix, checks);
  if (quick) {
    checks.skip(prefix + "steady state, steady window, fluid balance", "--quick: the channels have not filled yet");
    return;
  }
  check_steady_block(s["steady"], prefix, checks);
  const double balance = s["conservation"]["fluid_balance_pct"].get<double>();
  checks.expect(prefix + "fluid in = daughter + outlet over the window", std::abs(balance) <= 0.1,
                fmt::format("{:+.4f}% (band +-0.1%)", balance));
}

}  // namespace hs::study
