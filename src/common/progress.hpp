// SPDX-License-Identifier: MIT
// A one-line progress indicator with ETA for long runs; silent when stderr is not a terminal or in CI.
#pragma once

#include <chrono>
#include <string>

namespace hs::common {

class Progress {
 public:
  Progress(std::string label, long total, bool enabled = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Call often; redraws at most a few times per second. `done` counts from 0 to total.
  void update(long done);
  void finish();
  /// Human-readable duration, e.g. "1h02m", "3m05s", "12.4s".
  static std::string format_duration(double seconds);
  /// True when stderr is a terminal and the CI variable is unset.
  static bool terminal_attached();

 private:
  std::string label_;
  long total_;
  long first_done_ = -1;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace hs::common
