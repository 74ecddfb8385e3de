// SPDX-License-Identifier: MIT
// The state of one campaign run, kept in its folder so that any interruption can be resumed:
// status.json says done or failed; a checkpoint without it says resume; nothing says start. While a campaign runs it,
// attempts.json names its process.
#pragma once

#include <filesystem>
#include <string>

namespace hs::campaign {

/// running: a campaign's process runs it now (so --status shows it, and a second campaign on the folder leaves it).
enum class RunState { pending, resumable, running, done, failed };

struct RunRecord {
  std::filesystem::path dir;   // campaign/runs/<name>
  std::string name;
  RunState state = RunState::pending;
  std::string reason;          // why it failed
  double wall_s = 0.0;         // wall time of the finished run (all attempts)
  int attempts = 0;
  long pid = 0;                // the process running it (state running), else 0

  [[nodiscard]] std::filesystem::path case_file() const { return dir / "case.toml"; }
  [[nodiscard]] std::filesystem::path output_dir() const { return dir / "output"; }
  [[nodiscard]] std::filesystem::path summary_file() const { return output_dir() / "summary.json"; }
  [[nodiscard]] std::filesystem::path console_file() const { return dir / "console.txt"; }
};

/// Reads the state of the run in `dir` from its files.
RunRecord read_run_record(const std::filesystem::path& dir, const std::string& name);
/// Writes status.json atomically (done or failed, with reason, wall time and attempts).
void write_run_status(const RunRecord& record);
std::string to_string(RunState state);

/// Moves the output of an attempt that cannot be resumed (failed, or stopped before its first checkpoint) to
/// output.attempt-N, so a fresh start never overwrites it; does nothing when there is no output yet.
void set_aside_output(const RunRecord& record);

}  // namespace hs::campaign
