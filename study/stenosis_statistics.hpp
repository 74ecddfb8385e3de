// SPDX-License-Identifier: MIT
// The stenosis study's statistics from one run's time series (analysis/: MSER-5 steady start, batch means) and its
// checks. docs/stenosis.md gives every definition.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "study/series_statistics.hpp"

namespace hs::study {

/// Bins with fewer cell samples over the window than this are left out of the maximum of <DI>(x) (their mean is
/// noise: at 1000 samples the standard error of a mean DI is ~3e-4, below the closure's rmse 0.0024).
inline constexpr double kMinBinSamples = 1000.0;

/// The statistics of one run from its rows (columns as StenosisStudyMeasurement::columns()) and `layout`
/// (summary.json results.study_layout): "steady" (steady_block of cells present, mean DI, the outlet's fluid and RBC
/// fluxes), "profile" (per bin: x_m, wall_radius_m, cell_samples, di_mean, di_mean_se, di_sd (the cells' spread),
/// hematocrit, hematocrit_se, ux_mean_m_s, wall_shear_1_s, wall_shear_poiseuille_1_s (4 Q / (pi r^3)),
/// outside_di_share, outside_any_share), "di_max" (value, se, sd, x_m, from the throat in m and in constriction
/// lengths; enough_samples false when no bin reached kMinBinSamples and the maximum is over the bins holding any),
/// "di_upstream" and "di_downstream" (mean, se over their windows), "conservation" (fluid balance over the window,
/// cells in = out + present).
[[nodiscard]] nlohmann::json stenosis_statistics(const nlohmann::json& layout, const std::vector<std::string>& columns,
                                                 const Rows& rows);

/// The study's checks (each can fail, exit 1): cells in = out + present exactly; not --quick: steady state detected
/// and steady over the window, the fluid's balance over the window within 0.1% of the inflow.
void check_stenosis_study(const nlohmann::json& study, bool quick, const std::string& prefix, hs::common::CheckList& checks);

}  // namespace hs::study
