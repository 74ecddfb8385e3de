// SPDX-License-Identifier: MIT
// `hemoscale study bifurcation`: the seed paper's section 4.3 (after Stathoulopoulos et al. 2024) at alpha = 30, 60
// and 90 deg: runs cases/unresolved/bifurcation/angle-*, then one table and the figures (docs/bifurcation.md).
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/case_request.hpp"

namespace hs::study {

/// Runs each angle into OUTPUT/angle-A (OUTPUT: --output, else cases/unresolved/bifurcation/runs/study or
/// study-quick): a run with its summary.json is kept (resumable: a run with a checkpoint and no summary resumes).
/// Then OUTPUT/bifurcation_table.csv and .json (a key per angle, angle_30 ..., with s_h_daughter, s_h_outlet,
/// di_av, flux fractions, their standard errors, the profiles and DI histograms) and, unless --quick, the figures
/// (tools/plot_bifurcation.py). Exit 0 when every run's own checks and the study's checks pass, 1 otherwise.
int study_bifurcation(const hs::common::StudyOptions& options);

/// One angle's table row (flat numbers) from its run's summary.json and the study's statistics.
[[nodiscard]] nlohmann::json bifurcation_table_row(double angle_deg, const nlohmann::json& summary, const nlohmann::json& stats);

}  // namespace hs::study
