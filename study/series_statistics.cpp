// SPDX-License-Identifier: MIT
// The studies' shared time-series statistics.
#include "study/series_statistics.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analysis/steady_state.hpp"

namespace hs::study {
namespace {

// A steady series' halves agree within 3 standard errors, or within 1% of their size for a nearly noiseless one (the
// flow rates: the issue asks the fluid's balance to 0.1%, the split is reported to 2-3 digits).
constexpr double kHalvesSigmas = 3.0;
constexpr double kHalvesFloor = 0.01;

}  // namespace

Columns::Columns(const std::vector<std::string>& names) {
  for (std::size_t i = 0; i < names.size(); ++i) index_[names[i]] = i;
}

std::vector<double> Columns::series(const Rows& rows, const std::string& n) const {
  std::vector<double> x;
  const std::size_t c = at(n);
  for (const auto& r : rows) x.push_back(r[c]);
  return x;
}

/// Batch-means ratio: per batch of rows [start, end) the ratio of summed numerators to summed denominators; the mean
/// is the whole window's ratio, the error the batch ratios' spread over sqrt(batches).
hs::common::MeanWithError batch_ratio(const Rows& rows, std::size_t start, const RowFn& num, const RowFn& den) {
  std::vector<double> n_all;
  std::vector<double> d_all;
  double n_sum = 0.0;
  double d_sum = 0.0;
  for (std::size_t i = start; i < rows.size(); ++i) {
    n_all.push_back(num(rows[i]));
    d_all.push_back(den(rows[i]));
    n_sum += n_all.back();
    d_sum += d_all.back();
  }
  hs::common::MeanWithError out{.mean = d_sum != 0.0 ? n_sum / d_sum : 0.0, .standard_error = 0.0, .batches = 0};
  const std::size_t len = n_all.size() / kStudyBatches;
  if (len == 0) return out;
  std::vector<double> ratios;
  const std::size_t off = n_all.size() - len * kStudyBatches;
  for (int b = 0; b < kStudyBatches; ++b) {
    double nb = 0.0;
    double db = 0.0;
    for (std::size_t i = 0; i < len; ++i) {
      nb += n_all[off + static_cast<std::size_t>(b) * len + i];
      db += d_all[off + static_cast<std::size_t>(b) * len + i];
    }
    ratios.push_back(db != 0.0 ? nb / db : 0.0);
  }
  out.standard_error = hs::common::batch_means(ratios, kStudyBatches).standard_error;
  out.batches = kStudyBatches;
  return out;
}

/// Where every monitored series has settled (MSER-5) and whether each is steady from the latest start on.
nlohmann::json steady_block(const Columns& cols, const Rows& rows, const std::vector<std::string>& monitored, double dt) {
  std::size_t start = 0;
  bool all_found = true;
  for (const auto& name : monitored) {
    const auto s = hs::analysis::mser_truncation(cols.series(rows, name));
    all_found = all_found && s.found;
    start = std::max(start, s.start);
  }
  nlohmann::json list = nlohmann::json::array();
  bool all_agree = true;
  for (const auto& name : monitored) {
    const auto x = cols.series(rows, name);
    const auto s = hs::analysis::mser_truncation(x);
    const auto h = hs::analysis::halves_agree(x, start, kHalvesSigmas, kStudyBatches / 2, kHalvesFloor);
    all_agree = all_agree && h.agree;
    list.push_back({{"name", name}, {"found", s.found}, {"start_step", s.start}, {"first_half_mean", h.first_mean},
                    {"second_half_mean", h.second_mean}, {"combined_error", h.combined_error}, {"agree", h.agree}});
  }
  return {{"method", "MSER-5 start per series (White 1997), window after the latest; halves within 3 SE or 1%"},
          {"all_found", all_found}, {"all_agree", all_agree}, {"start_step", start},
          {"start_time_s", static_cast<double>(start) * dt}, {"window_steps", rows.size() - start}, {"series", list}};
}


nlohmann::json conservation_block(const Columns& cols, const Rows& rows, std::size_t start,
                                  const std::vector<std::string>& inlets, bool fluid_stores, double dt) {
  double in = 0.0;
  double out = 0.0;
  double cells_in = 0.0;
  double cells_out = 0.0;
  const std::string suffix = "_fluid_flux_m3_s";
  for (const auto& [c, index] : cols.all()) {
    if (c.size() < suffix.size() || c.substr(c.size() - suffix.size()) != suffix) continue;
    const std::string n = c.substr(0, c.size() - suffix.size());
    const bool inlet = std::find(inlets.begin(), inlets.end(), n) != inlets.end();
    for (std::size_t s = start; s < rows.size(); ++s) (inlet ? in : out) += rows[s][index];
    cells_in += rows.back()[cols.at(n + "_cells_in")];
    cells_out += rows.back()[cols.at(n + "_cells_out")];
  }
  const std::size_t plasma = cols.at("plasma_volume_m3");
  const double stored = fluid_stores ? rows.back()[plasma] - rows[start > 0 ? start - 1 : 0][plasma] : 0.0;
  const double steps = static_cast<double>(rows.size() - start);
  return {{"fluid_in_m3_s", in / steps}, {"fluid_out_m3_s", out / steps},
          {"fluid_balance_pct", in != 0.0 ? 100.0 * (out + stored / dt - in) / in : 0.0},
          {"cells_in", cells_in}, {"cells_out", cells_out}, {"cells_present", rows.back()[cols.at("cells_present")]}};
}

void check_cell_count(const nlohmann::json& c, const std::string& prefix, hs::common::CheckList& checks) {
  const double in = c["cells_in"].get<double>();
  const double out = c["cells_out"].get<double>();
  const double present = c["cells_present"].get<double>();
  checks.expect(prefix + "cells in at the openings = cells out + cells present (exact)", in == out + present,
                fmt::format("{:.0f} in, {:.0f} out, {:.0f} present", in, out, present));
}

void check_steady_block(const nlohmann::json& st, const std::string& prefix, hs::common::CheckList& checks) {
  std::string unsettled;
  std::string unsteady;
  for (const auto& x : st["series"]) {
    if (!x["found"].get<bool>()) unsettled += fmt::format(" {}", x["name"].get<std::string>());
    if (!x["agree"].get<bool>()) unsteady += fmt::format(" {} ({:.4g} then {:.4g} +- {:.2g})", x["name"].get<std::string>(),
                                                         x["first_half_mean"].get<double>(), x["second_half_mean"].get<double>(),
                                                         x["combined_error"].get<double>());
  }
  checks.expect(prefix + "steady state detected (MSER-5 start in the first half of every monitored series)", unsettled.empty(),
                unsettled.empty() ? fmt::format("from t = {:.4g} s", st["start_time_s"].get<double>()) : "not settled:" + unsettled);
  checks.expect(prefix + "steady over the window (halves within 3 SE or 1%)", unsteady.empty(),
                unsteady.empty() ? fmt::format("{} steps", st["window_steps"].get<long>()) : "drifting:" + unsteady);
}

}  // namespace hs::study
