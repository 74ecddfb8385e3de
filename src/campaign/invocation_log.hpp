// SPDX-License-Identifier: MIT
// When a campaign ran: one entry per invocation that ran something (start, last sign of life, runs finished), kept
// in CAMPAIGN_DIR/runs/invocations.json, so the campaign's wall time adds up across sittings and interruptions.
#pragma once

#include <filesystem>

namespace hs::campaign {

/// Opens a new entry (started = ended = now) in `file`; touch() moves its end to now. Written atomically each time,
/// so a killed campaign leaves its entry ending at its last touch (a finished run).
class InvocationLog {
 public:
  explicit InvocationLog(std::filesystem::path file);
  void touch(int runs_finished);

 private:
  void write() const;
  std::filesystem::path file_;
  std::size_t entry_ = 0;
  double started_s_ = 0.0;
  double ended_s_ = 0.0;
  int runs_finished_ = 0;
};

struct InvocationTotals {
  int invocations = 0;
  double wall_s = 0.0;   // sum of (ended - started)
};

/// The totals of `file`; zero when it does not exist. Throws ConfigError when it cannot be parsed.
InvocationTotals read_invocation_totals(const std::filesystem::path& file);

}  // namespace hs::campaign
