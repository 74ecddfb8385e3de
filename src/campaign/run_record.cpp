// SPDX-License-Identifier: MIT
// The state of one campaign run, kept in its folder.
#include "campaign/run_record.hpp"

#include <signal.h>

#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "common/io/atomic_file.hpp"
#include "common/io/checkpoint.hpp"

namespace hs::campaign {
namespace {

/// Whether process `pid` is alive and runs this run's case file (not a later process that reused the number).
bool runs_now(long pid, const RunRecord& r) {
  if (pid <= 0 || kill(static_cast<pid_t>(pid), 0) != 0) return false;
  std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline");
  const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The run's own folder name and file, as the path may be spelled relative to another directory.
  return cmdline.find(r.name + "/case.toml") != std::string::npos;
}

}  // namespace

std::string to_string(RunState state) {
  switch (state) {
    case RunState::pending: return "pending";
    case RunState::resumable: return "resumable";
    case RunState::running: return "running";
    case RunState::done: return "done";
    case RunState::failed: return "failed";
  }
  return "unknown";
}

RunRecord read_run_record(const std::filesystem::path& dir, const std::string& name) {
  RunRecord r;
  r.dir = dir;
  r.name = name;
  std::ifstream in(dir / "status.json");
  if (in) {
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_discarded()) {
      const std::string s = j.value("state", "");
      r.reason = j.value("reason", "");
      r.wall_s = j.value("wall_s", 0.0);
      r.attempts = j.value("attempts", 0);
      if (s == "done") r.state = RunState::done;
      if (s == "failed") r.state = RunState::failed;
      if (r.state != RunState::pending) return r;
    }
  }
  const auto progress = dir / "attempts.json";   // counts interrupted attempts between status writes
  std::ifstream pin(progress);
  if (pin) {
    const auto j = nlohmann::json::parse(pin, nullptr, false);
    if (!j.is_discarded()) {
      r.attempts = j.value("attempts", 0);
      r.wall_s = j.value("wall_s", 0.0);
      const long pid = j.value("pid", 0L);
      if (runs_now(pid, r)) {
        r.state = RunState::running;
        r.pid = pid;
        return r;
      }
    }
  }
  if (common::Checkpoint::exists(r.output_dir() / "checkpoint")) r.state = RunState::resumable;
  return r;
}

void write_run_status(const RunRecord& record) {
  nlohmann::json j{{"state", to_string(record.state)}, {"reason", record.reason}, {"wall_s", record.wall_s},
                   {"attempts", record.attempts}};
  if (record.state == RunState::running) j["pid"] = record.pid;
  const auto file = record.state == RunState::done || record.state == RunState::failed ? record.dir / "status.json"
                                                                                        : record.dir / "attempts.json";
  common::write_file_atomic(file, j.dump(2) + "\n");
}

void set_aside_output(const RunRecord& record) {
  const auto out = record.output_dir();
  if (!std::filesystem::exists(out) || std::filesystem::is_empty(out)) return;
  for (int n = 1;; ++n) {
    auto aside = out;
    aside += ".attempt-" + std::to_string(n);
    if (!std::filesystem::exists(aside)) {
      std::filesystem::rename(out, aside);
      return;
    }
  }
}

}  // namespace hs::campaign
