// SPDX-License-Identifier: MIT
#include "common/memory_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"

namespace hs::common {
namespace {

/// Lengths from 1 mm up are not cell scale (the largest device of the seed paper is a few hundred micrometres).
constexpr double kCellScaleLimit_m = 1e-3;

/// The kB value of a /proc/meminfo line "Name:   123 kB", in bytes; nothing found: a negative number.
double meminfo_bytes(const std::string& name) {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(name + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(name.size() + 1));
    double kb = -1.0;
    fields >> kb;
    return kb * 1024.0;
  }
  return -1.0;
}

/// A number from a cgroup v2 file ("max" or unreadable: infinity).
double cgroup_value(const char* file) {
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text == "max") return std::numeric_limits<double>::infinity();
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

std::string gib(double bytes) { return fmt::format("{:.3g} GiB", bytes / (1024.0 * 1024.0 * 1024.0)); }

}  // namespace

double available_memory_bytes() {
  double available = meminfo_bytes("MemAvailable");
  if (available < 0.0) {
    available = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  }
  const double headroom = cgroup_value("/sys/fs/cgroup/memory.max") - cgroup_value("/sys/fs/cgroup/memory.current");
  return std::min(available, headroom);
}

std::string micrometre_hint(double value_m) {
  if (!(value_m >= kCellScaleLimit_m)) return "";
  if (value_m >= 1.0) {   // a micrometre count written as metres
    return fmt::format(" ({:g} m; lengths are in metres: {:g} micrometres is written {:g}e-6)", value_m, value_m,
                       value_m);
  }
  return fmt::format(" ({:g} m is {:g} mm, not cell scale; lengths are in metres: 25 micrometres is written 25e-6)",
                     value_m, value_m * 1e3);
}

void require_memory(const ConfigFile& file, const MemoryNeed& need, std::span<const SizingKey> keys,
                    double available_bytes) {
  if (need.bytes <= available_bytes) return;
  std::string set_by, hints;
  for (const SizingKey& k : keys) {
    set_by += fmt::format("{}{} = {:g}", set_by.empty() ? "" : ", ", k.key, k.value);
    const std::string hint = k.is_length_m ? micrometre_hint(k.value) : "";
    if (!hint.empty()) hints += fmt::format("; {}{}", k.key, hint);
  }
  throw ConfigError(fmt::format("{}: the run needs ~{} for {} (set by {}), but this machine has {} available; "
                                "make the domain smaller or the spacing coarser{}",
                                file.name(), gib(need.bytes), need.what, set_by, gib(available_bytes), hints));
}

}  // namespace hs::common
