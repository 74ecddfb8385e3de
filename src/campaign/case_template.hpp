// SPDX-License-Identifier: MIT
// Writes the case file of one campaign run: the template with the run's grid values put into their keys.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "campaign/campaign_spec.hpp"

namespace hs::campaign {

/// One point of the grid: a value for every axis, in the axis order of the spec.
struct GridPoint {
  std::vector<GridValue> values;
};

/// Every point of the Cartesian product of the axes, first axis slowest.
std::vector<GridPoint> grid_points(const CampaignSpec& spec);

/// Folder name of a run, e.g. "r_star-0.2_re-0.1_setup-drag" (axis names and values joined).
std::string run_name(const CampaignSpec& spec, const GridPoint& point);

/// Reads the template, sets each axis' `case_key` (a dotted path; missing tables are created) to the point's
/// value, then the keys of the overrides that match the point (each named, with its reason, in a comment at the
/// top), and writes `file`. Throws ConfigError if the template is malformed or a key path crosses a non-table.
void write_run_case(const CampaignSpec& spec, const GridPoint& point, const std::filesystem::path& file);

}  // namespace hs::campaign
