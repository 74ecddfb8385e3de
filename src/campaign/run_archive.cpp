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
  std::size_t done = 0;
  while (done < content.size()) {
    const auto chunk = static_cast<unsigned>(std::min<std::size_t>(content.size() - done, 1u << 30));
    if (gzwrite(out, content.data() + done, chunk) != static_cast<int>(chunk)) {
      gzclose(out);
      throw std::runtime_error(fmt::format("write failed: {}", tmp.string()));
    }
    done += chunk;
  }
  if (gzclose(out) != Z_OK) throw std::runtime_error(fmt::format("write failed: {}", tmp.string()));
  fs::rename(tmp, file);
}

std::string read_gzip(const fs::path& file) {
  gzFile in = gzopen(file.c_str(), "rb");
  if (in == nullptr) throw std::runtime_error(fmt::format("cannot read {}", file.string()));
  std::string content;
  std::vector<char> buffer(1 << 20);
  int n = 0;
  while ((n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0) content.append(buffer.data(), n);
  const bool failed = n < 0;
  gzclose(in);
  if (failed) throw std::runtime_error(fmt::format("{}: corrupt gzip file", file.string()));
  return content;
}

/// The header and every k-th row (k so that at most kArchivedSeriesRows are kept), the last row always.
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
  common::write_file_atomic(dest / "status.json", read_text(run.dir / "status.json"));
  const fs::path series = run.output_dir() / "timeseries.csv";
  if (fs::exists(series)) write_gzip_atomic(dest / "timeseries.csv.gz", thinned_series(read_text(series)));
  fs::remove_all(archived_checkpoint_dir(run, archive));
}

void archive_checkpoint(const RunRecord& run, const fs::path& archive) {
  const fs::path source = run.output_dir() / "checkpoint";
  if (!common::Checkpoint::exists(source)) return;
  const fs::path dest = archived_checkpoint_dir(run, archive);
  fs::create_directories(dest);
  for (const auto& entry : fs::directory_iterator(source)) {   // one file per rank
    if (entry.path().extension() != ".bin") continue;
    write_gzip_atomic(dest / (entry.path().filename().string() + ".gz"), read_text(entry.path()));
  }
  // Attempts and wall time so far, so that they add up across machines.
  if (fs::exists(run.dir / "attempts.json")) common::write_file_atomic(dest / "attempts.json", read_text(run.dir / "attempts.json"));
}

bool restore_run(const RunRecord& run, const fs::path& archive) {
  const fs::path from = archive / run.name;
  const bool knows_nothing = run.state == RunState::pending && run.attempts == 0 && !fs::exists(run.output_dir());
  if (!knows_nothing || !fs::exists(from)) return false;
  if (fs::exists(from / "status.json") && fs::exists(from / "summary.json")) {
    fs::create_directories(run.output_dir());
    common::write_file_atomic(run.summary_file(), read_text(from / "summary.json"));
    common::write_file_atomic(run.dir / "status.json", read_text(from / "status.json"));
    return true;
  }
  const fs::path checkpoint = archived_checkpoint_dir(run, archive);
  if (!fs::exists(checkpoint)) return false;
  const fs::path dest = run.output_dir() / "checkpoint";
  fs::create_directories(dest);
  for (const auto& entry : fs::directory_iterator(checkpoint)) {
    if (entry.path().extension() != ".gz") continue;
    common::write_file_atomic(dest / entry.path().stem(), read_gzip(entry.path()));
  }
  if (fs::exists(checkpoint / "attempts.json")) {
    common::write_file_atomic(run.dir / "attempts.json", read_text(checkpoint / "attempts.json"));
  }
  return true;
}

}  // namespace hs::campaign
