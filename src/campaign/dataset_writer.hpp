// SPDX-License-Identifier: MIT
// Assembles the campaign's dataset CSV from the finished runs' summary.json files: one row per value of the
// row axes, columns taken from the runs of that row (e.g. Cd from the drag run, Cl from the lift run).
#pragma once

#include <vector>

#include "campaign/campaign_spec.hpp"
#include "campaign/run_record.hpp"

namespace hs::campaign {

/// Writes spec.dataset_file atomically. Rows whose runs are not all done are left out; returns the row count.
/// Cells: numbers with 10 significant digits, strings as they are, empty where a value is missing.
int write_dataset(const CampaignSpec& spec, const std::vector<RunRecord>& runs);

}  // namespace hs::campaign
