// SPDX-License-Identifier: MIT
// The part of a campaign that is committed (campaign.toml's `archive` folder), so that a fresh clone goes on where
// the last machine stopped: each finished run's summary.json, status.json and time series (thinned, gzip), and,
// while a run is unfinished, its latest checkpoint (gzip). The run folders themselves (CAMPAIGN_DIR/runs/) are
// scratch: full outputs, never committed.
#pragma once

#include <filesystem>

#include "campaign/run_record.hpp"

namespace hs::campaign {

/// About this many time-series rows are archived per run (every k-th sample, plus the last one): the
/// period averages are in summary.json; the series is for plots (tools/plot_tube_cell.py, tools/plot_cell_flow.py).
inline constexpr std::size_t kArchivedSeriesRows = 1000;

/// Copies a done run into `archive`/<name>/ and drops its archived checkpoint, if any. Files are replaced atomically.
void archive_finished_run(const RunRecord& run, const std::filesystem::path& archive);

/// Copies the checkpoint of an unfinished run into `archive`/<name>/checkpoint/ (gzip); does nothing without one.
void archive_checkpoint(const RunRecord& run, const std::filesystem::path& archive);

/// Drops a run's archived result and checkpoint (a run reopened or failed: the archive must not bring it back as
/// done or resumable).
void forget_archived_run(const RunRecord& run, const std::filesystem::path& archive);

/// For a run its own folder knows nothing about (a fresh clone): brings back from `archive` what is there, a
/// finished run (summary.json and status.json, so it is done and its dataset row is written) or a checkpoint (so it
/// resumes), and the case it ran. Returns true when something was restored; the caller reads the record again.
/// ConfigError for an archive entry that cannot be read.
bool restore_run(const RunRecord& run, const std::filesystem::path& archive);

}  // namespace hs::campaign
