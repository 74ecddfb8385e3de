// SPDX-License-Identifier: MIT
// Reads campaign.toml: the grid, its overrides and the dataset columns.
#include "campaign/campaign_spec.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"

namespace hs::campaign {

bool same_value(const GridValue& a, const GridValue& b) {
  if (a.index() != b.index()) return false;
  if (const auto* d = std::get_if<double>(&a)) return std::abs(*d - std::get<double>(b)) <= 1e-12 * std::max(1.0, std::abs(*d));
  return std::get<std::string>(a) == std::get<std::string>(b);
}

bool matches(const GridOverride& o, const std::vector<GridAxis>& axes, const std::vector<GridValue>& point) {
  for (const auto& [axis_name, value] : o.when) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      if (axes[i].name == axis_name && !same_value(point[i], value)) return false;
    }
  }
  return true;
}

std::string to_text(const GridValue& v) {
  if (const auto* d = std::get_if<double>(&v)) return fmt::format("{}", *d);
  return std::get<std::string>(v);
}

namespace {

GridAxis read_axis(common::ConfigSection axis, const std::string& name) {
  GridAxis a{name, axis.string("key"), {}};
  axis.forbid_together("values", "labels", "an axis is either numeric or labelled");
  if (axis.has("labels")) {
    for (auto& s : axis.strings("labels")) a.values.emplace_back(std::move(s));
  } else {
    for (double v : axis.numbers_in("values", -1e300, 1e300)) a.values.emplace_back(v);
  }
  return a;
}

std::string listed(const std::vector<GridValue>& values) {
  std::string out;
  for (const auto& v : values) out += (out.empty() ? "" : ", ") + to_text(v);
  return out;
}

std::string axis_names(const std::vector<GridAxis>& axes) {
  std::string out;
  for (const auto& a : axes) out += (out.empty() ? "" : ", ") + a.name;
  return out;
}

/// Two overrides that set the same key and can both match one run (no axis where they ask for different values).
bool overlap(const GridOverride& a, const GridOverride& b) {
  if (a.case_key != b.case_key) return false;
  for (const auto& [axis, value] : a.when) {
    for (const auto& [other_axis, other_value] : b.when) {
      if (axis == other_axis && !same_value(value, other_value)) return false;
    }
  }
  return true;
}

GridOverride read_override(common::ConfigSection o, const std::string& name, const std::vector<GridAxis>& axes) {
  // A number only: the keys it is for (tau caps, iteration counts, factors) are numbers.
  GridOverride g{name, {}, o.string("key"), o.number_in("value", -1e300, 1e300), o.string("why")};
  for (const auto& a : axes) {
    if (a.case_key == g.case_key) {
      o.fail("key", fmt::format("is [grid.{}]'s key: an override may not change a grid value (the run's name and "
                                "dataset row would no longer say what it ran)", a.name));
    }
  }
  if (g.why.find_first_of("\n\r") != std::string::npos) o.fail("why", "must be one line (it becomes a comment in case.toml)");
  auto when = o.section("when");
  const auto keys = when.keys();
  if (keys.empty()) o.fail("when", fmt::format("names no grid axis: give {{ axis = value, ... }} with axes of {}", axis_names(axes)));
  for (const auto& axis_name : keys) {
    const auto axis = std::find_if(axes.begin(), axes.end(), [&](const GridAxis& a) { return a.name == axis_name; });
    if (axis == axes.end()) when.fail(axis_name, fmt::format("is not a [grid] axis (axes: {})", axis_names(axes)));
    const bool labelled = std::holds_alternative<std::string>(axis->values.front());
    GridValue v = labelled ? GridValue(when.string(axis_name)) : GridValue(when.number_in(axis_name, -1e300, 1e300));
    if (std::none_of(axis->values.begin(), axis->values.end(), [&](const GridValue& x) { return same_value(x, v); })) {
      when.fail(axis_name, fmt::format("matches no run: the axis' values are {}", listed(axis->values)));
    }
    g.when.emplace_back(axis_name, std::move(v));
  }
  return g;
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> out;
  std::string part;
  for (char ch : text + ",") {
    if (ch == ',') {
      if (!part.empty()) out.push_back(part);
      part.clear();
    } else if (ch != ' ') {
      part += ch;
    }
  }
  return out;
}

}  // namespace

std::filesystem::path invocation_file(const CampaignSpec& spec) {
  return spec.archive_dir.empty() ? spec.dir / "runs" / "invocations.json" : spec.archive_dir / "invocations.json";
}

CampaignSpec read_campaign_spec(const std::filesystem::path& dir) {
  auto file = common::ConfigFile::load(dir / "campaign.toml", "campaign file");
  CampaignSpec spec;
  spec.dir = dir;
  auto root = file->root();
  auto c = root.section("campaign");
  spec.name = c.string("name");
  spec.template_case = c.file_path("template");
  if (!std::filesystem::is_regular_file(spec.template_case)) c.fail("template", "no such case file");
  spec.jobs = static_cast<int>(c.integer_in_or("jobs", 1, 64, 2));
  spec.threads_per_job = static_cast<int>(c.integer_in_or("threads_per_job", 1, 256, 1));
  if (!c.string_or("archive", "").empty()) spec.archive_dir = c.file_path("archive").lexically_normal();

  auto grid = root.section("grid");
  for (const auto& name : grid.keys()) spec.axes.push_back(read_axis(grid.section(name), name));
  if (spec.axes.empty()) throw common::ConfigError(file->name() + ": [grid] needs at least one axis [grid.NAME]");
  auto overrides = root.section_or_empty("override");
  for (const auto& name : overrides.keys()) {
    GridOverride o = read_override(overrides.section(name), name, spec.axes);
    for (const auto& earlier : spec.overrides) {
      if (overlap(earlier, o)) {
        overrides.section(name).fail("key", fmt::format("is also set by [override.{}] for some of the same runs: which "
                                                        "value wins would be unclear; make their 'when' disjoint",
                                                        earlier.name));
      }
    }
    spec.overrides.push_back(std::move(o));
  }

  auto d = root.section("dataset");
  spec.dataset_file = d.file_path("file");
  for (const auto& name : split_names(d.string("row_axes"))) {
    if (std::none_of(spec.axes.begin(), spec.axes.end(), [&](const GridAxis& a) { return a.name == name; })) {
      d.fail("row_axes", fmt::format("'{}' is not a [grid] axis", name));
    }
    spec.row_axes.push_back(name);
  }
  auto columns = d.section("columns");
  for (const auto& name : columns.keys()) {
    auto col = columns.section(name);
    DatasetColumn dc{name, col.string("pointer"), col.string_or("only_axis", ""), col.string_or("only_value", ""),
                     col.string_or("pointer_before_schema_1", "")};
    if (!dc.only_axis.empty() &&
        std::none_of(spec.axes.begin(), spec.axes.end(), [&](const GridAxis& a) { return a.name == dc.only_axis; })) {
      col.fail("only_axis", "is not a [grid] axis");
    }
    spec.columns.push_back(std::move(dc));
  }
  file->finish();
  return spec;
}

}  // namespace hs::campaign
