// SPDX-License-Identifier: MIT
// A time step as a list of named stages; the names label the wall-clock timers (STYLE R8).
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hs::common {

class TimeLoop {
 public:
  /// Runs steps first_step+1 .. end_step (so a resumed loop continues where it stopped).
  explicit TimeLoop(long end_step, long first_step = 0);

  /// A stage run every step, in the order added.
  void add(std::string name, std::function<void()> stage);
  /// A stage run after every `interval`-th step (interval <= 0 disables it).
  void every(long interval, std::string name, std::function<void()> stage);
  /// Runs to the end; `on_step` (if given) is called after each step, e.g. to update a progress line.
  void run(const std::function<void(long)>& on_step = {});
  /// Runs `n` steps (or fewer at the end); returns false once the loop is finished.
  bool run_steps(long n);

  [[nodiscard]] long step() const { return step_; }
  [[nodiscard]] long end_step() const { return end_step_; }
  /// The pace of this loop's own steps: wall seconds since it was made per simulated ms, for a time step dt_s. A
  /// resumed loop counts only the steps it ran, so a run's pace stays right across restarts and stages; 0 before any.
  [[nodiscard]] double wall_s_per_simulated_ms(double dt_s) const;
  /// Wall seconds per stage, and their share of the total.
  [[nodiscard]] nlohmann::json timings() const;
  [[nodiscard]] std::string timing_table() const;

 private:
  struct Stage {
    std::string name;
    long interval;
    std::function<void()> fn;
    double seconds = 0.0;
    long calls = 0;
  };
  void run_one_step();

  long end_step_;
  long first_step_;
  long step_;
  std::chrono::steady_clock::time_point made_ = std::chrono::steady_clock::now();
  std::vector<Stage> stages_;
};

}  // namespace hs::common
