// SPDX-License-Identifier: MIT
// Run log: diagnostics go to stderr, result lines to stdout (rank 0 only), and both to the run folder's log.txt.
#include "common/log.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace hs::common {
namespace {

const char* tag(Log::Level level) {
  switch (level) {
    case Log::Level::debug: return "debug";
    case Log::Level::info: return "info";
    case Log::Level::warning: return "warning";
    case Log::Level::error: return "error";
  }
  return "";
}

}  // namespace

std::string local_timestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  localtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", &tm);
  return buf;
}

Log::Log(int rank, Level threshold) : rank_(rank), threshold_(threshold) {}

void Log::open_file(const std::filesystem::path& file) {
  if (rank_ == 0) file_.open(file, std::ios::app);
}

void Log::write(Level level, const std::string& message) {
  if (level < threshold_ || rank_ != 0) return;
  if (!quiet_ || level >= Level::warning) {
    if (level == Level::info) {
      std::fprintf(stderr, "%s%s\n", prefix_.c_str(), message.c_str());
    } else {
      std::fprintf(stderr, "%s%s: %s\n", prefix_.c_str(), tag(level), message.c_str());
    }
  }
  if (file_.is_open()) {
    file_ << local_timestamp() << ' ' << prefix_ << tag(level) << ": " << message << '\n';
    file_.flush();
  }
}

void Log::write_result(const std::string& message) {
  if (rank_ != 0) return;
  std::fprintf(stdout, "%s%s\n", prefix_.c_str(), message.c_str());
  std::fflush(stdout);   // in order with the diagnostics when both go to one terminal or file
  if (file_.is_open()) {
    file_ << local_timestamp() << ' ' << prefix_ << "result: " << message << '\n';
    file_.flush();
  }
}

}  // namespace hs::common
