// SPDX-License-Identifier: MIT
// The shared opening and closing of every `hemoscale run`: strict check of the case file, the run folder
// (new, given, or resumed), the log, case.resolved.toml, and summary.json with provenance and wall time.
#pragma once

#include <chrono>
#include <memory>

#include <nlohmann/json.hpp>

#include "common/case_request.hpp"
#include "common/check_list.hpp"
#include "common/log.hpp"
#include "common/run_folder.hpp"

namespace hs::common {

class RunContext {
 public:
  /// Call after the case has read all its keys: rejects unknown keys (ConfigError), then creates or reopens
  /// the run folder (rank 0 decides, every rank gets the same path), opens log.txt and writes
  /// case.resolved.toml. MPI must be initialised.
  static RunContext start(const CaseRequest& request, const std::string& case_type);

  [[nodiscard]] const RunFolder& folder() const { return *folder_; }
  [[nodiscard]] Log& log() { return *log_; }
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int ranks() const { return ranks_; }
  [[nodiscard]] bool resuming() const { return resume_; }
  /// --quick: the coarse CI version of the case; recorded in case.resolved.toml, summary.json and every log line.
  [[nodiscard]] bool quick() const { return quick_; }
  [[nodiscard]] bool show_progress() const { return show_progress_ && rank_ == 0; }
  [[nodiscard]] double wall_seconds() const;

  /// Writes summary.json (rank 0) in the one layout of every case (summary_schema.hpp, docs/outputs.md): the case's
  /// blocks `results`, `groups`, `numerics`, `timings` (only those; a missing one is written empty), the checks'
  /// verdict, and schema version, case type, `quick`, provenance, wall time and ranks. Returns the summary written.
  nlohmann::json write_summary(nlohmann::json blocks, const CheckList& checks = {}) const;

 private:
  RunContext() = default;
  std::unique_ptr<RunFolder> folder_;
  std::unique_ptr<Log> log_;
  std::string case_type_;
  int rank_ = 0;
  int ranks_ = 1;
  bool resume_ = false;
  bool quick_ = false;
  bool show_progress_ = true;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hs::common
