// SPDX-License-Identifier: MIT
// The output folder of one run.
#include "common/run_folder.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <ctime>
#include <fstream>

#include <fmt/format.h>

#include "build_info.hpp"
#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"
#include "common/io/checkpoint.hpp"

namespace hs::common {

RunFolder::RunFolder(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::filesystem::create_directories(vtk_dir());
  std::filesystem::create_directories(checkpoint_dir());
}

RunFolder RunFolder::create_new(const std::filesystem::path& parent, std::string_view prefix) {
  std::filesystem::create_directories(parent);
  for (int i = 1; i < 100000; ++i) {
    const auto dir = parent / fmt::format("{}-{:03d}", prefix, i);
    if (::mkdir(dir.c_str(), 0755) == 0) return RunFolder(dir);
    if (errno != EEXIST) throw ConfigError(fmt::format("{}: cannot create run folder", dir.string()));
  }
  throw ConfigError(fmt::format("{}: no free run folder name left", parent.string()));
}

RunFolder RunFolder::create_exact(const std::filesystem::path& dir) {
  if (std::filesystem::exists(dir) && !std::filesystem::is_empty(dir)) {
    throw ConfigError(fmt::format("{}: output folder exists and is not empty; choose another "
                                  "(outputs are never overwritten) or use --resume",
                                  dir.string()));
  }
  std::filesystem::create_directories(dir);
  return RunFolder(dir);
}

RunFolder RunFolder::open_existing(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) throw ConfigError(fmt::format("{}: no such run folder to resume", dir.string()));
  return RunFolder(dir);
}

bool resume_finds_complete_run(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) {
    throw ConfigError(fmt::format("{}: no such run folder to resume", dir.string()));
  }
  if (Checkpoint::exists(dir / "checkpoint")) return false;
  // write_summary() is a run's last act and adds the provenance: a summary.json with it means the run finished.
  if (std::ifstream in(dir / "summary.json"); in) {
    const auto summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (summary.is_object() && summary.contains("provenance")) return true;
  }
  throw ConfigError(fmt::format("{}: --resume: no checkpoint to continue from ({} is missing) and the run did not "
                                "finish (no summary.json); nothing was changed. Start it again without --resume into "
                                "a new folder (outputs are never overwritten)",
                                dir.string(), Checkpoint::file_for(dir / "checkpoint", 0).string()));
}

nlohmann::json provenance() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return {{"version", build_info::version},   {"git_commit", build_info::git_commit},
          {"git_dirty", build_info::git_dirty}, {"build_type", build_info::build_type},
          {"host", host},                       {"written_utc", when}};
}

void write_json(const std::filesystem::path& file, const nlohmann::json& summary) {
  // A --json FILE in a folder that does not exist yet is the user's new results folder, not an error.
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  write_file_atomic(file, summary.dump(2) + "\n");
}

}  // namespace hs::common
