// SPDX-License-Identifier: MIT
// When a campaign ran: one entry per invocation, in CAMPAIGN_DIR/runs/invocations.json.
#include "campaign/invocation_log.hpp"

#include <chrono>
#include <ctime>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"

namespace hs::campaign {
namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// "2026-11-23T05:38:38Z", for a person reading the file.
std::string utc_text(double seconds) {
  const auto t = static_cast<std::time_t>(seconds);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json read_entries(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return nlohmann::json::array();
  std::ifstream in(file);
  try {
    nlohmann::json j = nlohmann::json::parse(in);
    if (!j.is_array()) throw common::ConfigError(fmt::format("{}: expected a JSON array of invocations", file.string()));
    return j;
  } catch (const nlohmann::json::exception& e) {
    throw common::ConfigError(fmt::format("{}: not valid JSON ({}); move it aside to start a new record", file.string(),
                                          e.what()));
  }
}

}  // namespace

InvocationLog::InvocationLog(std::filesystem::path file) : file_(std::move(file)), started_s_(now_s()), ended_s_(started_s_) {
  entry_ = read_entries(file_).size();
  write();
}

void InvocationLog::touch(int runs_finished) {
  ended_s_ = now_s();
  runs_finished_ = runs_finished;
  write();
}

void InvocationLog::write() const {
  nlohmann::json entries = read_entries(file_);
  const nlohmann::json mine = {{"started_utc", utc_text(started_s_)}, {"ended_utc", utc_text(ended_s_)},
                               {"started_s", started_s_}, {"wall_s", ended_s_ - started_s_},
                               {"runs_finished", runs_finished_}};
  if (entry_ < entries.size()) {
    entries[entry_] = mine;
  } else {
    entries.push_back(mine);
  }
  common::write_file_atomic(file_, entries.dump(1) + "\n");
}

InvocationTotals read_invocation_totals(const std::filesystem::path& file) {
  InvocationTotals t;
  for (const auto& e : read_entries(file)) {
    ++t.invocations;
    t.wall_s += e.value("wall_s", 0.0);
  }
  return t;
}

}  // namespace hs::campaign
