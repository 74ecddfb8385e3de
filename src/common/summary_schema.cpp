// SPDX-License-Identifier: MIT
#include "common/summary_schema.hpp"

#include <set>
#include <stdexcept>

#include <fmt/format.h>

namespace hs::common {
namespace {

using Problems = std::vector<std::string>;

/// The case's own blocks: objects, any content.
const std::set<std::string> kCaseBlocks{"results", "groups", "numerics", "timings"};

void require(Problems& p, const nlohmann::json& s, const std::string& key, bool (nlohmann::json::*is)() const noexcept,
             const char* kind) {
  if (!s.contains(key)) {
    p.push_back(fmt::format("`{}` is missing ({} expected)", key, kind));
  } else if (!(s.at(key).*is)()) {
    p.push_back(fmt::format("`{}` is {}, not {}", key, s.at(key).type_name(), kind));
  }
}

void check_checks(Problems& p, const nlohmann::json& s) {
  if (!s.contains("checks") || !s.at("checks").is_array()) return;   // reported by require()
  int failed = 0;
  int skipped = 0;
  for (const auto& c : s.at("checks")) {
    const bool ok = c.is_object() && c.contains("name") && c.at("name").is_string() && c.contains("status") &&
                    c.at("status").is_string() && c.contains("detail") && c.at("detail").is_string();
    if (!ok) {
      p.push_back(fmt::format("a check is not {{name, status, detail}} (strings): {}", c.dump()));
      continue;
    }
    const std::string status = c.at("status").get<std::string>();
    if (status == "failed") ++failed;
    else if (status == "skipped") ++skipped;
    else if (status != "passed") p.push_back(fmt::format("check `{}`: status `{}` is not passed, failed or skipped",
                                                         c.at("name").get<std::string>(), status));
  }
  if (s.contains("passed") && s.at("passed").is_boolean() && s.at("passed").get<bool>() != (failed == 0)) {
    p.push_back(fmt::format("`passed` is {} with {} failed checks", s.at("passed").dump(), failed));
  }
  if (s.contains("checks_failed") && s.at("checks_failed") != failed) p.push_back("`checks_failed` miscounts the checks");
  if (s.contains("checks_skipped") && s.at("checks_skipped") != skipped) p.push_back("`checks_skipped` miscounts the checks");
}

void check_groups_and_timings(Problems& p, const nlohmann::json& s) {
  if (s.contains("groups") && s.at("groups").is_object()) {
    for (const auto& [name, value] : s.at("groups").items()) {
      if (!value.is_number()) p.push_back(fmt::format("group `{}` is {}, not a number", name, value.type_name()));
    }
  }
  if (s.contains("timings") && s.at("timings").is_object()) {
    for (const auto& [stage, t] : s.at("timings").items()) {
      if (!t.is_object() || !t.contains("seconds") || !t.at("seconds").is_number()) {
        p.push_back(fmt::format("timing `{}` has no number `seconds`", stage));
      }
    }
  }
}

}  // namespace

std::vector<std::string> summary_schema_problems(const nlohmann::json& s) {
  Problems p;
  if (!s.is_object()) return {fmt::format("summary is {}, not an object", s.type_name())};
  if (!s.contains("schema_version") || s.at("schema_version") != kSummarySchemaVersion) {
    p.push_back(fmt::format("`schema_version` is not {}", kSummarySchemaVersion));
  }
  require(p, s, "case_type", &nlohmann::json::is_string, "a string");
  require(p, s, "quick", &nlohmann::json::is_boolean, "a boolean");
  require(p, s, "passed", &nlohmann::json::is_boolean, "a boolean");
  require(p, s, "checks", &nlohmann::json::is_array, "an array");
  require(p, s, "checks_failed", &nlohmann::json::is_number_integer, "an integer");
  require(p, s, "checks_skipped", &nlohmann::json::is_number_integer, "an integer");
  for (const auto& block : kCaseBlocks) require(p, s, block, &nlohmann::json::is_object, "an object");
  require(p, s, "provenance", &nlohmann::json::is_object, "an object");
  require(p, s, "wall_time_s", &nlohmann::json::is_number, "a number");
  require(p, s, "mpi_ranks", &nlohmann::json::is_number_integer, "an integer");
  // Optional: summaries written before it was added (same schema) have none.
  if (s.contains("peak_memory_GiB") && !s.at("peak_memory_GiB").is_number()) {
    p.push_back(fmt::format("`peak_memory_GiB` is {}, not a number", s.at("peak_memory_GiB").type_name()));
  }
  if (s.contains("provenance") && s.at("provenance").is_object()) {
    for (const char* key : {"version", "git_commit", "build_type", "host", "written_utc"}) {
      if (!s.at("provenance").contains(key)) p.push_back(fmt::format("`provenance.{}` is missing", key));
    }
  }
  check_checks(p, s);
  check_groups_and_timings(p, s);
  static const std::set<std::string> known{"schema_version", "case_type",  "quick",      "passed",
                                           "checks",         "checks_failed", "checks_skipped", "results",
                                           "groups",         "numerics",   "timings",    "provenance",
                                           "wall_time_s",    "mpi_ranks",  "peak_memory_GiB"};
  for (const auto& [key, value] : s.items()) {
    if (!known.count(key)) p.push_back(fmt::format("`{}` is no key of the layout: a case's values go under results, "
                                                   "groups, numerics or timings", key));
  }
  return p;
}

nlohmann::json assemble_summary(nlohmann::json blocks, const CheckList& checks, const SummaryRun& run) {
  if (!blocks.is_object()) blocks = nlohmann::json::object();
  for (const auto& block : kCaseBlocks) {
    if (!blocks.contains(block)) blocks[block] = nlohmann::json::object();
  }
  nlohmann::json s = {{"schema_version", kSummarySchemaVersion}, {"case_type", run.case_type}, {"quick", run.quick}};
  checks.write_to(s);
  for (const auto& [key, value] : blocks.items()) {
    if (!kCaseBlocks.count(key)) {
      throw std::logic_error(fmt::format("summary.json of {}: `{}` is no case block (results, groups, numerics, timings)",
                                         run.case_type, key));
    }
    s[key] = value;
  }
  s["provenance"] = run.provenance;
  s["wall_time_s"] = run.wall_time_s;
  s["mpi_ranks"] = run.mpi_ranks;
  s["peak_memory_GiB"] = run.peak_memory_GiB;
  const Problems p = summary_schema_problems(s);
  if (!p.empty()) {
    std::string all;
    for (const auto& x : p) all += "\n  " + x;
    throw std::logic_error(fmt::format("summary.json of {} departs from schema {}:{}", run.case_type,
                                       kSummarySchemaVersion, all));
  }
  return s;
}

}  // namespace hs::common
