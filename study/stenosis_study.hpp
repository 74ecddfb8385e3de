// SPDX-License-Identifier: MIT
// `hemoscale study stenosis`: the seed paper's section 4.4 (Figs. 17-18): RBCs through a 150 um tube with an 85 um
// and a 55 um throat (cases/unresolved/stenosis/throat-*), then one table, the plasma-only checks and the figures
// (docs/stenosis.md).
#pragma once

#include <nlohmann/json.hpp>

#include "common/case_request.hpp"

namespace hs::study {

/// Runs each throat into OUTPUT/throat-NNum (OUTPUT: --output, else cases/unresolved/stenosis/runs/study or
/// study-quick). Resumable: a run whose fingerprint (OUTPUT/throat-NNum.fingerprint: the case file's values,
/// the closures' text, --quick) matches is kept when finished, resumed from its checkpoint when not; a run folder with
/// another fingerprint is refused (ConfigError: remove it). Then the plasma-only check of each throat at the case's
/// dx and at dx / 2 (pressure drop, throat centreline velocity), OUTPUT/stenosis_table.csv and .json (a key per
/// throat, throat_85um and throat_55um, with di_max, x_di_max_m, di_upstream, di_downstream, their errors, the
/// profiles along x, the hemolysis index, conservation and the plasma check) and, unless --quick, the figures
/// (tools/plot_stenosis_study.py). Exit 0 when every run's own checks and the study's checks pass, 1 otherwise (a run
/// that did not reach a steady state among them).
int study_stenosis(const hs::common::StudyOptions& options);

/// One throat's table row (flat numbers) from its run's summary.json and the study's statistics.
[[nodiscard]] nlohmann::json stenosis_table_row(double throat_m, const nlohmann::json& summary, const nlohmann::json& stats);

}  // namespace hs::study
