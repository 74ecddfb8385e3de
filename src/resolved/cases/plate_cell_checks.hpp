// SPDX-License-Identifier: MIT
// What a shear or migration run must show, from its case file's optional [check] section: the flow mode and the
// tumbling period against Jeffery's (shear), the migration toward the centreline (migration). A check the run is too
// short to decide (a --quick run, say) is skipped with the reason, never passed.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/cases/plate_cell_series.hpp"

namespace hs::resolved {

/// `results` is PlateCellSeries::results() of the same run.
[[nodiscard]] hs::common::CheckList plate_cell_checks(const PlateCellConfig& c, const nlohmann::json& results,
                                                      const std::vector<PlateCellSample>& samples);

}  // namespace hs::resolved
