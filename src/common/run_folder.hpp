// SPDX-License-Identifier: MIT
// The output folder of one run: never overwritten, holding the case as run, the summary, time series,
// VTK series, checkpoints and the log (DESIGN.md "Inputs and outputs").
#pragma once

#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

namespace hs::common {

class RunFolder {
 public:
  /// A new folder `parent/prefix-NNN` with the first free NNN (mkdir is the atomic claim, so two runs
  /// started together never share a folder). Creates vtk/ and checkpoint/ inside.
  static RunFolder create_new(const std::filesystem::path& parent, std::string_view prefix = "run");
  /// A folder given by the user: must not exist yet (or exist empty), so nothing is overwritten.
  static RunFolder create_exact(const std::filesystem::path& dir);
  /// An existing run folder, to resume into.
  static RunFolder open_existing(const std::filesystem::path& dir);

  [[nodiscard]] const std::filesystem::path& path() const { return dir_; }
  [[nodiscard]] std::filesystem::path file(std::string_view name) const { return dir_ / name; }
  [[nodiscard]] std::filesystem::path vtk_dir() const { return dir_ / "vtk"; }
  [[nodiscard]] std::filesystem::path checkpoint_dir() const { return dir_ / "checkpoint"; }

 private:
  explicit RunFolder(std::filesystem::path dir);
  std::filesystem::path dir_;
};

/// The one rule for `--resume` (every case, before it builds anything): true when `dir` holds a finished run
/// (summary.json written, no checkpoint left to continue), which the caller reports as complete and leaves untouched;
/// false when there is a checkpoint to continue from. Throws ConfigError when `dir` is no run folder, or holds neither
/// a checkpoint nor a finished run, since rerunning from the start would overwrite its outputs.
[[nodiscard]] bool resume_finds_complete_run(const std::filesystem::path& dir);

/// Version, git commit, build type, host, time: the provenance block of every summary.json (STYLE R12).
nlohmann::json provenance();
/// Writes `summary` (pretty-printed) atomically.
void write_json(const std::filesystem::path& file, const nlohmann::json& summary);

}  // namespace hs::common
