// SPDX-License-Identifier: MIT
// The bifurcation study's statistics from one run's time series (analysis/: MSER-5 steady start, batch means, S_H,
// histograms) and its checks. docs/bifurcation.md gives every definition.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "study/series_statistics.hpp"

namespace hs::study {

/// The statistics of one run from its rows (columns as BifurcationStudyMeasurement::columns()) and `layout`
/// (summary.json results.study_layout, unresolved/cases/bifurcation_study_measurement.hpp): "steady" (the MSER-5 start of
/// every monitored series, the window after the latest, the halves test of each), per daughter "branches".NAME (w,
/// hematocrit and its standard error per bin, cut_hematocrit, s_h and s_h_se, blood and RBC flux fractions with
/// standard errors), "di" per branch and "all" (counts, below, above, cell_samples, di_av, di_av_se,
/// fraction_above), "conservation" (fluid balance over the window, cells in = out + present).
[[nodiscard]] nlohmann::json bifurcation_statistics(const nlohmann::json& layout, const std::vector<std::string>& columns,
                                                    const std::vector<std::vector<double>>& rows);

/// The study's checks (each can fail, exit 1): cells in = out + present exactly; not --quick: every monitored
/// series settled (MSER-5 start inside the first half), each steady over the window (halves within 3 standard
/// errors or 1%), the fluid's balance over the window within 0.1% of the inflow. `study`: bifurcation_statistics'.
/// Each check's name starts with `prefix` (e.g. "angle-30: ").
void check_bifurcation_study(const nlohmann::json& study, bool quick, const std::string& prefix, hs::common::CheckList& checks);

}  // namespace hs::study
