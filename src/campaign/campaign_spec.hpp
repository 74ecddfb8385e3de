// SPDX-License-Identifier: MIT
// What a campaign.toml asks for: a case template, a grid of parameter values mapped onto its keys, how many
// runs at once, and which summary.json results form the dataset.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace hs::campaign {

using GridValue = std::variant<double, std::string>;

/// One axis of the grid: its values are written into `case_key` (a dotted path like "flow.reynolds").
/// In campaign.toml an axis has either `values = [numbers]` or `labels = ["strings"]`.
struct GridAxis {
  std::string name;
  std::string case_key;
  std::vector<GridValue> values;
};

/// One dataset column: a number taken from each run's summary.json at `json_pointer` ("/results/di_mean"),
/// from the runs whose axis `only_axis` has the value `only_value` (empty: any run of the row). A run archived before
/// summary.json's schema 1 (no `schema_version`) is read at `pointer_before_schema_1` when that is given ("/dx_m").
struct DatasetColumn {
  std::string name;
  std::string json_pointer;
  std::string only_axis;
  std::string only_value;
  std::string pointer_before_schema_1;
};

/// An exception to the template for part of the grid, with its reason: the runs whose axes have all the values in
/// `when` get `case_key` (not a grid axis' key) set to `value`, a number. Two overrides of one key must not match a
/// common run. In campaign.toml:
///   [override.NAME]  when = { re = 0.4, setup = "drag" }  key = "numerics.max_tau"  value = 12.5  why = "..."
struct GridOverride {
  std::string name;
  std::vector<std::pair<std::string, GridValue>> when;   // axis name -> value
  std::string case_key;
  double value = 0.0;
  std::string why;
};

struct CampaignSpec {
  std::filesystem::path dir;                 // the campaign folder
  std::string name;
  std::filesystem::path template_case;       // case.toml every run starts from
  int jobs = 2;                              // runs at the same time
  int threads_per_job = 1;                   // OMP_NUM_THREADS of each run
  std::vector<GridAxis> axes;
  std::vector<GridOverride> overrides;
  std::filesystem::path dataset_file;
  std::filesystem::path archive_dir;         // committed copy of finished runs and checkpoints (empty: none)
  std::vector<std::string> row_axes;         // axes that make a row (the others are merged into it)
  std::vector<DatasetColumn> columns;
};

/// Where the campaign's invocations are recorded: in the archive when there is one (so the wall time adds up across
/// machines), else CAMPAIGN_DIR/runs/invocations.json.
std::filesystem::path invocation_file(const CampaignSpec& spec);

/// Reads and checks `dir/campaign.toml` (strict: ConfigError naming key and value on any problem).
CampaignSpec read_campaign_spec(const std::filesystem::path& dir);

/// Grid values compare equal when of one kind and, for numbers, within 1e-12 relative (both are parsed from text).
bool same_value(const GridValue& a, const GridValue& b);

/// Whether a run with these axis values (in the spec's axis order) is one the override is for.
bool matches(const GridOverride& o, const std::vector<GridAxis>& axes, const std::vector<GridValue>& point);

/// Text of a grid value as it appears in run names and dataset cells ("0.3", "drag").
std::string to_text(const GridValue& v);

}  // namespace hs::campaign
