// SPDX-License-Identifier: MIT
// Refuses a case whose arrays cannot fit in this machine's memory, before anything is allocated or written, and says
// which keys sized it (with a hint when a length looks like micrometres written as metres).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace hs::common {

class ConfigFile;

/// Bytes this machine can still give: MemAvailable of /proc/meminfo, lowered to the cgroup's memory.max headroom
/// where one is set; the physical memory when /proc/meminfo is unreadable.
[[nodiscard]] double available_memory_bytes();

/// A case-file value that sets the size of the run, as the message should quote it.
struct SizingKey {
  std::string key;          // "[geometry] radius_m"
  double value = 0.0;       // as the file gives it (SI)
  bool is_length_m = false; // a length in metres: checked for micrometres given as metres
};

/// What a run is about to allocate: `what` names it ("a lattice of 51 x 51 x 101 nodes"), `bytes` estimates it.
struct MemoryNeed {
  std::string what;
  double bytes = 0.0;
};

/// A parenthesised hint ("25 m; ... 25 micrometres is written 25e-6") when `value_m`, a length meant at cell scale, is
/// 1 mm or more; empty otherwise. Cell-scale cases (resolved cells, microchannels) span micrometres to a few hundred of them.
[[nodiscard]] std::string micrometre_hint(double value_m);

/// Throws ConfigError "<file>: needs ~X GiB for WHAT (set by KEY = V, ...) but Y GiB are available; ..." when
/// need.bytes exceeds `available_bytes`, with a micrometre hint for every length key that looks like one.
void require_memory(const ConfigFile& file, const MemoryNeed& need, std::span<const SizingKey> keys,
                    double available_bytes = available_memory_bytes());

}  // namespace hs::common
