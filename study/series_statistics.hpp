// SPDX-License-Identifier: MIT
// What every study's statistics do with a run's time series (timeseries.csv): columns by name, the MSER-5 steady
// start of the monitored series with the halves test, and batch-means ratios. Shared by the bifurcation and
// stenosis studies.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/batch_means.hpp"
#include "common/check_list.hpp"

namespace hs::study {

/// Batches per window for every standard error (batch means, common/batch_means.hpp).
inline constexpr int kStudyBatches = 10;

using Rows = std::vector<std::vector<double>>;
using RowFn = std::function<double(const std::vector<double>&)>;

/// Column index by name.
class Columns {
 public:
  explicit Columns(const std::vector<std::string>& names);
  [[nodiscard]] bool has(const std::string& n) const { return index_.count(n) > 0; }
  [[nodiscard]] std::size_t at(const std::string& n) const { return index_.at(n); }
  [[nodiscard]] std::vector<double> series(const Rows& rows, const std::string& n) const;
  [[nodiscard]] const std::map<std::string, std::size_t>& all() const { return index_; }

 private:
  std::map<std::string, std::size_t> index_;
};

/// Batch-means ratio: per batch of rows [start, end) the ratio of summed numerators to summed denominators; the mean
/// is the whole window's ratio, the error the batch ratios' spread over sqrt(batches).
[[nodiscard]] hs::common::MeanWithError batch_ratio(const Rows& rows, std::size_t start, const RowFn& num, const RowFn& den);

/// Where every monitored series has settled (MSER-5, White 1997) and whether each is steady from the latest start on
/// (halves within 3 standard errors or 1%): "all_found", "all_agree", "start_step", "start_time_s", "window_steps",
/// "series" (per series: found, start_step, the halves' means, their combined error, agree).
[[nodiscard]] nlohmann::json steady_block(const Columns& cols, const Rows& rows, const std::vector<std::string>& monitored, double dt);

/// Conservation over the run: the fluid over rows [start, end) (summed inflow of the `inlets`' NAME_fluid_flux_m3_s
/// columns against every other opening's, plus what the domain stored when `fluid_stores`: "fluid_in_m3_s",
/// "fluid_out_m3_s", "fluid_balance_pct" of the inflow) and the cells at the end ("cells_in", "cells_out",
/// "cells_present").
[[nodiscard]] nlohmann::json conservation_block(const Columns& cols, const Rows& rows, std::size_t start,
                                                const std::vector<std::string>& inlets, bool fluid_stores, double dt);

/// Cells in at the openings = cells out + cells present, exactly (a conservation_block).
void check_cell_count(const nlohmann::json& conservation, const std::string& prefix, hs::common::CheckList& checks);

/// The two checks on a steady_block: every series settled in its first half; each steady over the window.
void check_steady_block(const nlohmann::json& steady, const std::string& prefix, hs::common::CheckList& checks);

}  // namespace hs::study
