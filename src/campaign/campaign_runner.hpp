// SPDX-License-Identifier: MIT
// Runs every point of a campaign grid as its own `hemoscale run`, a few at a time, unattended: finished runs
// are never rerun, interrupted ones resume from their checkpoint, failed ones are recorded with their reason
// and do not stop the others. The dataset is rewritten after every finished run.
#pragma once

#include <filesystem>
#include <vector>

#include "campaign/campaign_spec.hpp"
#include "campaign/run_record.hpp"

namespace hs::campaign {

struct CampaignOptions {
  std::filesystem::path executable;   // the hemoscale binary that runs each case
  bool retry_failed = false;          // run failed runs again
  bool reopen_done = false;           // run finished runs again: from their last checkpoint (after a stricter stopping
                                      // rule a run that now settles later goes on), or afresh without one
  bool show_progress = true;
  int max_runs = -1;                  // stop after starting this many runs (-1: all); for tests and trials
};

class CampaignRunner {
 public:
  CampaignRunner(CampaignSpec spec, CampaignOptions options);

  /// The records of every run, read from disk. `prepare`: each run gets its folder and case file, and runs the folder
  /// knows nothing about are first brought back from the archive (run_archive.hpp); without it nothing is written.
  std::vector<RunRecord> records(bool prepare) const;
  /// Runs what is left; returns the number of runs that failed (now or before).
  int run();
  /// A table of every run's state, for `hemoscale campaign DIR --status`.
  std::string status_table() const;

 private:
  CampaignSpec spec_;
  CampaignOptions options_;
};

}  // namespace hs::campaign
