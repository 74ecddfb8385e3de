// SPDX-License-Identifier: MIT
// Run log: messages go to stderr (rank 0 only) and to the run folder's log.txt.
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

}  // namespace hs::common
