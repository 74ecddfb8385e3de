// SPDX-License-Identifier: MIT
// Progress with ETA for long runs: a redrawn line on a terminal, dated lines in a log file, nothing in CI.
#include "common/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

#include "common/log.hpp"

namespace hs::common {

namespace {

bool in_ci() { return std::getenv("CI") != nullptr; }

}  // namespace

Progress::Progress(std::string label, long total, bool enabled, std::chrono::seconds log_every)
    : label_(std::move(label)), total_(total),
      mode_(!enabled || in_ci() ? Mode::off : (isatty(STDERR_FILENO) != 0 ? Mode::terminal : Mode::log)),
      log_every_(log_every), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

Progress::~Progress() { finish(); }

std::string Progress::format_duration(double s) {
  if (s < 60.0) return fmt::format("{:.1f}s", s);
  const long total = static_cast<long>(s + 0.5);
  if (total < 3600) return fmt::format("{}m{:02d}s", total / 60, total % 60);
  return fmt::format("{}h{:02d}m", total / 3600, (total % 3600) / 60);
}

std::string Progress::status_text(long done) const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const long progressed = done - first_done_;   // a resumed run estimates from where it restarted
  std::string eta = "--";
  if (eta_estimate_) {
    const double left = eta_estimate_(done);
    if (left >= 0.0) eta = format_duration(left);
  } else if (progressed > 0) {
    eta = format_duration(elapsed * static_cast<double>(total_ - done) / static_cast<double>(progressed));
  }
  return fmt::format("{} {:5.1f}%  {}/{}  elapsed {}  ETA {}", label_, 100.0 * fraction, done, total_,
                     format_duration(elapsed), eta);
}

void Progress::update(long done) {
  if (mode_ == Mode::off || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (first_done_ < 0) first_done_ = done;
  latest_done_ = done;
  if (mode_ == Mode::terminal) {
    if (now - last_draw_ < std::chrono::milliseconds(250) && done < total_ && line_open_) return;
    std::fprintf(stderr, "\r%s   ", status_text(done).c_str());
    line_open_ = true;
  } else {
    const bool due = done != last_done_ && (now - last_draw_ >= log_every_ || done >= total_);
    if (!due) return;
    std::fprintf(stderr, "%s  %s\n", local_timestamp().c_str(), status_text(done).c_str());
    last_done_ = done;
  }
  last_draw_ = now;
  std::fflush(stderr);
}

void Progress::note(const std::string& line) {
  if (mode_ == Mode::off) return;
  if (mode_ == Mode::terminal) {
    // Over the progress line (erased to the end of the line); the next update() draws it again below.
    std::fprintf(stderr, "\r\033[K%s\n", line.c_str());
    line_open_ = false;
  } else {
    std::fprintf(stderr, "%s  %s\n", local_timestamp().c_str(), line.c_str());
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (mode_ == Mode::off || finished_) return;
  finished_ = true;
  if (mode_ == Mode::terminal && line_open_) std::fprintf(stderr, "\n");
  // A log ends with where the run stopped (it may stop before its total: settled, interrupted).
  if (mode_ == Mode::log && latest_done_ >= 0 && latest_done_ != last_done_) {
    std::fprintf(stderr, "%s  %s\n", local_timestamp().c_str(), status_text(latest_done_).c_str());
  }
  std::fflush(stderr);
}

}  // namespace hs::common
