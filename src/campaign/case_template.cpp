// SPDX-License-Identifier: MIT
// Writes the case file of one campaign run.
#include "campaign/case_template.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"

namespace hs::campaign {

std::vector<GridPoint> grid_points(const CampaignSpec& spec) {
  std::vector<GridPoint> points{GridPoint{}};
  for (const auto& axis : spec.axes) {
    std::vector<GridPoint> next;
    for (const auto& p : points) {
      for (const auto& v : axis.values) {
        GridPoint q = p;
        q.values.push_back(v);
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  return points;
}

std::string run_name(const CampaignSpec& spec, const GridPoint& point) {
  std::string name;
  for (std::size_t i = 0; i < spec.axes.size(); ++i) {
    name += fmt::format("{}{}-{}", i ? "_" : "", spec.axes[i].name, to_text(point.values[i]));
  }
  return name;
}

namespace {

/// Sets the dotted `key` of `doc` (missing tables are created); `where` names the campaign.toml entry for errors.
template <class Value>
void set_key(toml::table& doc, const std::string& key, Value value, const std::string& where) {
  toml::table* t = &doc;
  std::size_t start = 0;
  for (auto dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    const std::string part = key.substr(start, dot - start);
    if (!t->contains(part)) t->insert(part, toml::table{});
    t = t->get(part)->as_table();
    if (t == nullptr) {
      throw common::ConfigError(fmt::format("{} key = \"{}\": '{}' is not a table in the template", where, key, part));
    }
    start = dot + 1;
  }
  t->insert_or_assign(key.substr(start), std::move(value));
}

/// An override's number as the template holds that key: a count (an integer there, e.g. numerics.membrane_every)
/// stays an integer, which the case reader requires; anything else is a float.
void set_override(toml::table& doc, const GridOverride& o, const std::string& where) {
  const toml::node_view<toml::node> current = doc.at_path(o.case_key);
  if (current.is_integer()) {
    if (o.value != std::floor(o.value)) {
      throw common::ConfigError(fmt::format("{} value = {}: {} is an integer in the template; give an integer", where,
                                            o.value, o.case_key));
    }
    set_key(doc, o.case_key, static_cast<std::int64_t>(o.value), where);
  } else {
    set_key(doc, o.case_key, o.value, where);
  }
}

}  // namespace

void write_run_case(const CampaignSpec& spec, const GridPoint& point, const std::filesystem::path& file) {
  toml::table doc;
  try {
    doc = toml::parse_file(spec.template_case.string());
  } catch (const toml::parse_error& e) {
    throw common::ConfigError(fmt::format("{}: malformed TOML: {}", spec.template_case.string(), e.description()));
  }
  const std::string campaign_file = (spec.dir / "campaign.toml").string();
  for (std::size_t i = 0; i < spec.axes.size(); ++i) {
    const std::string where = fmt::format("{}: [grid.{}]", campaign_file, spec.axes[i].name);
    if (const auto* d = std::get_if<double>(&point.values[i])) {
      set_key(doc, spec.axes[i].case_key, *d, where);
    } else {
      set_key(doc, spec.axes[i].case_key, std::get<std::string>(point.values[i]), where);
    }
  }
  std::string applied;
  for (const GridOverride& o : spec.overrides) {
    if (!matches(o, spec.axes, point.values)) continue;
    set_override(doc, o, fmt::format("{}: [override.{}]", campaign_file, o.name));
    applied += fmt::format("# [override.{}] {} = {}: {}\n", o.name, o.case_key, o.value, o.why);
  }
  std::ostringstream text;
  text << "# Written by `hemoscale campaign` from " << spec.template_case.filename().string() << " with "
       << run_name(spec, point) << "\n" << applied << doc << "\n";
  common::write_file_atomic(file, text.str());
}

}  // namespace hs::campaign
