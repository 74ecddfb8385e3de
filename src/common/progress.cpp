// SPDX-License-Identifier: MIT
// A one-line progress indicator with ETA for long runs.
#include "common/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

namespace hs::common {

Progress::Progress(std::string label, long total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled && terminal_attached()),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

Progress::~Progress() { finish(); }

bool Progress::terminal_attached() { return isatty(STDERR_FILENO) != 0 && std::getenv("CI") == nullptr; }

std::string Progress::format_duration(double s) {
  if (s < 60.0) return fmt::format("{:.1f}s", s);
  const long total = static_cast<long>(s + 0.5);
  if (total < 3600) return fmt::format("{}m{:02d}s", total / 60, total % 60);
  return fmt::format("{}h{:02d}m", total / 3600, (total % 3600) / 60);
}

void Progress::update(long done) {
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (first_done_ < 0) first_done_ = done;   // a resumed run estimates from where it restarted
  if (now - last_draw_ < std::chrono::milliseconds(250) && done < total_) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const long progressed = done - first_done_;
  std::string eta = "--";
  if (progressed > 0) {
    eta = format_duration(elapsed * static_cast<double>(total_ - done) / static_cast<double>(progressed));
  }
  std::fprintf(stderr, "\r%s %5.1f%%  %ld/%ld  elapsed %s  ETA %s   ", label_.c_str(), 100.0 * fraction, done, total_,
               format_duration(elapsed).c_str(), eta.c_str());
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  std::fprintf(stderr, "\n");
}

}  // namespace hs::common
