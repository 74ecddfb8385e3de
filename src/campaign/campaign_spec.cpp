// SPDX-License-Identifier: MIT
// Reads campaign.toml.
#include "campaign/campaign_spec.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"

namespace hs::campaign {

namespace {
bool same_value(const GridValue& a, const GridValue& b);
}  // namespace

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

bool same_value(const GridValue& a, const GridValue& b) {
  if (a.index() != b.index()) return false;
  if (const auto* d = std::get_if<double>(&a)) return std::abs(*d - std::get<double>(b)) <= 1e-12 * std::max(1.0, std::abs(*d));
  return std::get<std::string>(a) == std::get<std::string>(b);
}

GridOverride read_override(common::ConfigSection o, const std::string& name, const std::vector<GridAxis>& axes) {
  GridOverride g{name, {}, o.string("key"), o.number_in("value", -1e300, 1e300), o.string("why")};
  auto when = o.section("when");
  const auto keys = when.keys();
  if (keys.empty()) o.fail("when", "names no grid axis: give { axis = value, ... }");
  for (const auto& axis_name : keys) {
    const auto axis = std::find_if(axes.begin(), axes.end(), [&](const GridAxis& a) { return a.name == axis_name; });
    if (axis == axes.end()) when.fail(axis_name, "is not a [grid] axis");
    const bool labelled = std::holds_alternative<std::string>(axis->values.front());
    GridValue v = labelled ? GridValue(when.string(axis_name)) : GridValue(when.number_in(axis_name, -1e300, 1e300));
    if (std::none_of(axis->values.begin(), axis->values.end(), [&](const GridValue& x) { return same_value(x, v); })) {
      when.fail(axis_name, fmt::format("{} is not one of the axis' values: the override would match no run", to_text(v)));
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

CampaignSpec read_campaign_spec(const std::filesystem::path& dir) {
  auto file = common::ConfigFile::load(dir / "campaign.toml");
  CampaignSpec spec;
  spec.dir = dir;
  auto root = file->root();
  auto c = root.section("campaign");
  spec.name = c.string("name");
  spec.template_case = c.file_path("template");
  if (!std::filesystem::is_regular_file(spec.template_case)) c.fail("template", "no such case file");
  spec.jobs = static_cast<int>(c.integer_in_or("jobs", 1, 64, 2));
  spec.threads_per_job = static_cast<int>(c.integer_in_or("threads_per_job", 1, 256, 1));

  auto grid = root.section("grid");
  for (const auto& name : grid.keys()) spec.axes.push_back(read_axis(grid.section(name), name));
  if (spec.axes.empty()) throw common::ConfigError(file->name() + ": [grid] needs at least one axis [grid.NAME]");
  auto overrides = root.section_or_empty("override");
  for (const auto& name : overrides.keys()) spec.overrides.push_back(read_override(overrides.section(name), name, spec.axes));

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
    DatasetColumn dc{name, col.string("pointer"), col.string_or("only_axis", ""), col.string_or("only_value", "")};
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
