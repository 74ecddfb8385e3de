// SPDX-License-Identifier: MIT
// Progress with ETA for long runs: a redrawn line on a terminal, dated lines in a log file, nothing in CI.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace hs::common {

class Progress {
 public:
  /// On a terminal the line is redrawn a few times per second. Otherwise (stderr redirected to a log, a run left
  /// in the background) a dated line is written when `done` has moved and `log_every` has passed since the last
  /// one, and at the end. Silent when !enabled or the CI variable is set.
  Progress(std::string label, long total, bool enabled = true,
           std::chrono::seconds log_every = std::chrono::seconds(300));
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Call often. `done` counts from 0 to total.
  void update(long done);
  /// The seconds left as the caller estimates them, in place of the rate since the start (which misleads when the
  /// units differ in size or were part-done before: a resumed campaign's runs). Negative: no estimate ("--").
  void set_eta_estimate(std::function<double(long done)> seconds_left) { eta_estimate_ = std::move(seconds_left); }
  /// One line of news (a run finished), on its own line above the progress line; dated in a log.
  void note(const std::string& line);
  void finish();
  /// Human-readable duration, e.g. "1h02m", "3m05s", "12.4s".
  static std::string format_duration(double seconds);

 private:
  enum class Mode { off, terminal, log };
  [[nodiscard]] std::string status_text(long done) const;

  std::string label_;
  long total_;
  long first_done_ = -1;
  long latest_done_ = -1;      // the count of the last update()
  long last_done_ = -1;        // log: the count of the last line written
  Mode mode_;
  bool finished_ = false;
  bool line_open_ = false;     // terminal: a progress line is drawn and not yet ended
  std::chrono::seconds log_every_;
  std::function<double(long)> eta_estimate_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace hs::common
