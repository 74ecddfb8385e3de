// SPDX-License-Identifier: MIT
// The process's peak resident set size: run summaries and the benchmarks report it.
#pragma once

#include <fstream>
#include <string>

namespace hs::common {

/// Peak resident set size of this process (VmHWM of /proc/self/status), GiB; 0 where /proc is not available.
/// VmHWM only grows: in one process it is the largest size measured so far.
inline double peak_memory_gib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / (1024.0 * 1024.0);   // kB -> GiB
  }
  return 0.0;
}

}  // namespace hs::common
