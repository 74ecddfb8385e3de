// SPDX-License-Identifier: MIT
// Assembles the campaign's dataset CSV from the finished runs.
#include "campaign/dataset_writer.hpp"

#include <fstream>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "campaign/case_template.hpp"
#include "common/io/atomic_file.hpp"

namespace hs::campaign {
namespace {

std::string cell(const nlohmann::json& summary, const DatasetColumn& col) {
  const bool before_schema_1 = summary.is_object() && !summary.contains("schema_version");
  const nlohmann::json::json_pointer p(before_schema_1 && !col.pointer_before_schema_1.empty() ? col.pointer_before_schema_1
                                                                                                  : col.json_pointer);
  if (!summary.contains(p)) return "";
  const auto& v = summary.at(p);
  if (v.is_number()) return fmt::format("{:.10g}", v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return "";
}

}  // namespace

int write_dataset(const CampaignSpec& spec, const std::vector<RunRecord>& runs) {
  const auto points = grid_points(spec);
  // Group runs by the values of the row axes, keeping the grid's order.
  std::vector<std::string> row_keys;
  std::map<std::string, std::vector<std::pair<const GridPoint*, const RunRecord*>>> rows;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string key;   // in the order of row_axes, as the header
    for (const auto& r : spec.row_axes) {
      for (std::size_t a = 0; a < spec.axes.size(); ++a) {
        if (spec.axes[a].name == r) key += to_text(points[i].values[a]) + ",";
      }
    }
    if (!rows.count(key)) row_keys.push_back(key);
    rows[key].emplace_back(&points[i], &runs[i]);
  }
  std::string text;
  for (const auto& r : spec.row_axes) text += r + ",";
  for (std::size_t c = 0; c < spec.columns.size(); ++c) text += spec.columns[c].name + (c + 1 < spec.columns.size() ? "," : "");
  text += "\n";
  int written = 0;
  for (const auto& key : row_keys) {
    const auto& members = rows[key];
    bool complete = true;
    std::vector<nlohmann::json> summaries;
    for (const auto& [point, run] : members) {
      complete = complete && run->state == RunState::done;
      std::ifstream in(run->summary_file());
      summaries.push_back(in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json());
    }
    if (!complete) continue;
    std::string line = key;
    for (std::size_t c = 0; c < spec.columns.size(); ++c) {
      const auto& col = spec.columns[c];
      std::string value;
      for (std::size_t m = 0; m < members.size(); ++m) {
        bool match = col.only_axis.empty();
        for (std::size_t a = 0; a < spec.axes.size() && !match; ++a) {
          match = spec.axes[a].name == col.only_axis && to_text(members[m].first->values[a]) == col.only_value;
        }
        if (match && !summaries[m].is_discarded()) {
          value = cell(summaries[m], col);
          break;
        }
      }
      line += value + (c + 1 < spec.columns.size() ? "," : "");
    }
    text += line + "\n";
    ++written;
  }
  std::filesystem::create_directories(spec.dataset_file.parent_path());
  common::write_file_atomic(spec.dataset_file, text);
  return written;
}

}  // namespace hs::campaign
