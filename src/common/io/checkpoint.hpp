// SPDX-License-Identifier: MIT
// Restart files: named arrays plus a JSON header in one file per rank, replaced atomically, so a killed
// run resumes from its last complete checkpoint and loses at most one interval.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hs::common {

class Checkpoint {
 public:
  /// Solver state as arrays of doubles or 64-bit integers; `meta` holds scalars (step, time, seed, ...).
  void put(const std::string& name, std::span<const double> values);
  void put(const std::string& name, std::span<const std::int64_t> values);
  nlohmann::json& meta() { return meta_; }
  [[nodiscard]] const nlohmann::json& meta() const { return meta_; }

  [[nodiscard]] bool has(const std::string& name) const;
  /// Throws std::runtime_error naming the array if absent or of the other type.
  [[nodiscard]] const std::vector<double>& doubles(const std::string& name) const;
  [[nodiscard]] const std::vector<std::int64_t>& integers(const std::string& name) const;

  /// Writes `dir/state.rankNNNN.bin` atomically (temp + rename).
  void write(const std::filesystem::path& dir, int rank = 0) const;
  /// Reads it back; throws ConfigError when missing or corrupt (truncated, wrong magic).
  static Checkpoint read(const std::filesystem::path& dir, int rank = 0);
  static bool exists(const std::filesystem::path& dir, int rank = 0);
  static std::filesystem::path file_for(const std::filesystem::path& dir, int rank);

 private:
  nlohmann::json meta_ = nlohmann::json::object();
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<std::int64_t>> integers_;
};

/// Says when the next checkpoint is due: every `interval_s` of wall time (DESIGN: "every N minutes").
class CheckpointSchedule {
 public:
  explicit CheckpointSchedule(double interval_s);
  /// True once per elapsed interval; resets the clock when it returns true.
  bool due();

 private:
  double interval_s_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace hs::common
