// SPDX-License-Identifier: MIT
// Run log: diagnostics go to stderr, result lines to stdout (rank 0 only), and both to the run folder's log.txt.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace hs::common {

/// Local wall-clock time, "2026-11-23 04:41:12", for lines a person reads later (log.txt, a campaign's log).
std::string local_timestamp();

class Log {
 public:
  enum class Level { debug, info, warning, error };

  /// `rank` != 0 writes nothing to stderr (MPI runs print once).
  explicit Log(int rank = 0, Level threshold = Level::info);
  /// Also write every message to `file` (appending, so a resumed run keeps its history).
  void open_file(const std::filesystem::path& file);
  void set_quiet(bool quiet) { quiet_ = quiet; }
  /// Put before every message (e.g. "[--quick] ").
  void set_prefix(std::string prefix) { prefix_ = std::move(prefix); }

  void write(Level level, const std::string& message);

  template <typename... Args>
  void info(fmt::format_string<Args...> f, Args&&... args) {
    write(Level::info, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void warning(fmt::format_string<Args...> f, Args&&... args) {
    write(Level::warning, fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void error(fmt::format_string<Args...> f, Args&&... args) {
    write(Level::error, fmt::format(f, std::forward<Args>(args)...));
  }
  /// A result line, the numbers the run was made for: on stdout (so `hemoscale run CASE > results.txt` keeps them apart
  /// from the diagnostics on stderr), also with --quiet, with the prefix ("[--quick] "), and in log.txt as "result:".
  template <typename... Args>
  void result(fmt::format_string<Args...> f, Args&&... args) {
    write_result(fmt::format(f, std::forward<Args>(args)...));
  }
  template <typename... Args>
  void debug(fmt::format_string<Args...> f, Args&&... args) {
    write(Level::debug, fmt::format(f, std::forward<Args>(args)...));
  }

 private:
  void write_result(const std::string& message);

  int rank_;
  Level threshold_;
  bool quiet_ = false;
  std::string prefix_;
  std::ofstream file_;
};

}  // namespace hs::common
