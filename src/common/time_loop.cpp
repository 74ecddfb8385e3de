// SPDX-License-Identifier: MIT
// A time step as a list of named stages with timers.
#include "common/time_loop.hpp"

#include <chrono>

#include <fmt/format.h>

namespace hs::common {

TimeLoop::TimeLoop(long end_step, long first_step) : end_step_(end_step), first_step_(first_step), step_(first_step) {}

void TimeLoop::add(std::string name, std::function<void()> stage) { stages_.push_back({std::move(name), 1, std::move(stage)}); }

void TimeLoop::every(long interval, std::string name, std::function<void()> stage) {
  if (interval > 0) stages_.push_back({std::move(name), interval, std::move(stage)});
}

void TimeLoop::run_one_step() {
  ++step_;
  for (auto& s : stages_) {
    if (step_ % s.interval != 0) continue;
    const auto t0 = std::chrono::steady_clock::now();
    s.fn();
    s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++s.calls;
  }
}

void TimeLoop::run(const std::function<void(long)>& on_step) {
  while (step_ < end_step_) {
    run_one_step();
    if (on_step) on_step(step_);
  }
}

bool TimeLoop::run_steps(long n) {
  for (long i = 0; i < n && step_ < end_step_; ++i) run_one_step();
  return step_ < end_step_;
}

double TimeLoop::wall_s_per_simulated_ms(double dt_s) const {
  const double simulated_ms = 1e3 * dt_s * static_cast<double>(step_ - first_step_);
  if (simulated_ms <= 0.0) return 0.0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - made_).count() / simulated_ms;
}

nlohmann::json TimeLoop::timings() const {
  double total = 0.0;
  for (const auto& s : stages_) total += s.seconds;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& s : stages_) {
    out[s.name] = {{"seconds", s.seconds}, {"calls", s.calls}, {"share", total > 0 ? s.seconds / total : 0.0}};
  }
  return out;
}

std::string TimeLoop::timing_table() const {
  double total = 0.0;
  for (const auto& s : stages_) total += s.seconds;
  std::string out = fmt::format("{:<28} {:>10} {:>7} {:>10}\n", "stage", "seconds", "share", "calls");
  for (const auto& s : stages_) {
    out += fmt::format("{:<28} {:>10.3f} {:>6.1f}% {:>10}\n", s.name, s.seconds, total > 0 ? 100.0 * s.seconds / total : 0.0,
                       s.calls);
  }
  return out;
}

}  // namespace hs::common
