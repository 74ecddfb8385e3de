// SPDX-License-Identifier: MIT
// The committed part of a campaign: finished runs and the checkpoints of unfinished ones.
#include "campaign/run_archive.hpp"

#include <unistd.h>
#include <zlib.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"
#include "common/io/checkpoint.hpp"

namespace hs::campaign {
namespace fs = std::filesystem;
namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// gzip with a zero time stamp (zlib's gzip header has none), so the same content gives the same bytes and
/// re-archiving leaves committed files unchanged. Written to a temporary first, then renamed.
void write_gzip_atomic(const fs::path& file, const std::string& content) {
  const fs::path tmp = file.string() + fmt::format(".tmp{}", ::getpid());
  gzFile out = gzopen(tmp.c_str(), "wb6");
  if (out == nullptr) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
  bool ok = true;
  for (std::size_t done = 0; ok && done < content.size();) {
    const auto chunk = static_cast<unsigned>(std::min<std::size_t>(content.size() - done, 1u << 30));
    ok = gzwrite(out, content.data() + done, chunk) == static_cast<int>(chunk);
    done += chunk;
  }
  ok = gzclose(out) == Z_OK && ok;
  if (!ok) {
    fs::remove(tmp);   // nothing half-written is left in the (committed) archive
    throw std::runtime_error(fmt::format("write failed: {}", tmp.string()));
  }
  fs::rename(tmp, file);
}

/// A truncated or non-gzip file is a ConfigError: gzread returns what it has and only gzclose sees the stream end early.
std::string read_gzip(const fs::path& file) {
  gzFile in = gzopen(file.c_str(), "rb");
  if (in == nullptr) throw common::ConfigError(fmt::format("cannot read {}", file.string()));
  std::string content;
  std::vector<char> buffer(1 << 20);
  int n = 0;
  while ((n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0) content.append(buffer.data(), n);
  const bool plain = gzdirect(in) != 0;
  const int closed = gzclose(in);
  if (n < 0 || plain || closed != Z_OK) {
    throw common::ConfigError(fmt::format("{}: not a complete gzip file; delete its run's folder in the archive to run it "
                                          "afresh", file.string()));
  }
  return content;
}

/// The header and every k-th row (k so that at most kArchivedSeriesRows are taken), plus the last row.
std::string thinned_series(const std::string& csv) {
  std::vector<std::string> lines;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  if (lines.empty()) return "";
  const std::size_t rows = lines.size() - 1;
  const std::size_t step = std::max<std::size_t>(1, (rows + kArchivedSeriesRows - 1) / kArchivedSeriesRows);
  std::string out = lines[0] + "\n";
  for (std::size_t i = 0; i < rows; i += step) out += lines[1 + i] + "\n";
  if (rows > 0 && (rows - 1) % step != 0) out += lines.back() + "\n";
  return out;
}

fs::path archived_checkpoint_dir(const RunRecord& run, const fs::path& archive) { return archive / run.name / "checkpoint"; }

}  // namespace

void archive_finished_run(const RunRecord& run, const fs::path& archive) {
  const fs::path dest = archive / run.name;
  fs::create_directories(dest);
  common::write_file_atomic(dest / "summary.json", read_text(run.summary_file()));
  if (fs::exists(run.case_file())) common::write_file_atomic(dest / "case.toml", read_text(run.case_file()));
  const fs::path series = run.output_dir() / "timeseries.csv";
  if (fs::exists(series)) write_gzip_atomic(dest / "timeseries.csv.gz", thinned_series(read_text(series)));
  fs::remove_all(archived_checkpoint_dir(run, archive));
  // Last: status.json marks the entry complete (the runner archives a done run again while it is missing).
  common::write_file_atomic(dest / "status.json", read_text(run.dir / "status.json"));
}

void archive_checkpoint(const RunRecord& run, const fs::path& archive) {
  const fs::path source = run.output_dir() / "checkpoint";
  if (!common::Checkpoint::exists(source)) return;
  const fs::path dest = archived_checkpoint_dir(run, archive);
  fs::create_directories(dest);
  // The case it started with: a resumed run must not pick up campaign.toml as edited since.
  if (fs::exists(run.case_file())) common::write_file_atomic(archive / run.name / "case.toml", read_text(run.case_file()));
  for (const auto& entry : fs::directory_iterator(source)) {   // one file per rank
    if (entry.path().extension() != ".bin") continue;
    write_gzip_atomic(dest / (entry.path().filename().string() + ".gz"), read_text(entry.path()));
  }
  // Attempts and wall time so far, so that they add up across machines.
  if (fs::exists(run.dir / "attempts.json")) common::write_file_atomic(dest / "attempts.json", read_text(run.dir / "attempts.json"));
}

void forget_archived_run(const RunRecord& run, const fs::path& archive) {
  fs::remove(archive / run.name / "status.json");   // first: the entry is no longer a finished run
  fs::remove(archive / run.name / "summary.json");
  fs::remove(archive / run.name / "timeseries.csv.gz");
  fs::remove_all(archived_checkpoint_dir(run, archive));
}

bool restore_run(const RunRecord& run, const fs::path& archive) {
  const fs::path from = archive / run.name;
  const bool knows_nothing = run.state == RunState::pending && run.attempts == 0 && !fs::exists(run.output_dir());
  if (!knows_nothing || !fs::exists(from)) return false;
  const bool finished = fs::exists(from / "status.json");
  const fs::path checkpoint = archived_checkpoint_dir(run, archive);
  if (!finished && !fs::exists(checkpoint)) return false;
  if (finished) {
    const auto status = nlohmann::json::parse(read_text(from / "status.json"), nullptr, false);
    if (status.is_discarded() || status.value("state", "") != "done" || !fs::exists(from / "summary.json")) {
      throw common::ConfigError(fmt::format("{}: not the status of a finished run with its summary.json beside it; "
                                            "delete {} to run it afresh", (from / "status.json").string(), from.string()));
    }
  }
  // Into a side folder first, renamed into place at the end: an interrupted restore leaves nothing that looks like
  // a run's output, so the next invocation restores again.
  const fs::path staging = run.dir / "output.restoring";
  fs::remove_all(staging);
  fs::create_directories(staging);
  if (fs::exists(from / "case.toml")) common::write_file_atomic(run.case_file(), read_text(from / "case.toml"));
  if (finished) {
    common::write_file_atomic(staging / "summary.json", read_text(from / "summary.json"));
  } else {
    fs::create_directories(staging / "checkpoint");
    for (const auto& entry : fs::directory_iterator(checkpoint)) {
      if (entry.path().extension() != ".gz") continue;
      common::write_file_atomic(staging / "checkpoint" / entry.path().stem(), read_gzip(entry.path()));
    }
    if (fs::exists(checkpoint / "attempts.json")) {
      common::write_file_atomic(run.dir / "attempts.json", read_text(checkpoint / "attempts.json"));
    }
  }
  fs::rename(staging, run.output_dir());
  if (finished) common::write_file_atomic(run.dir / "status.json", read_text(from / "status.json"));
  return true;
}

}  // namespace hs::campaign
