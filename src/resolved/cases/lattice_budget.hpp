// SPDX-License-Identifier: MIT
// The memory check every lattice case makes before it creates its run folder or allocates anything.
#pragma once

#include <array>
#include <initializer_list>

#include "common/config/config_file.hpp"
#include "common/memory_budget.hpp"

namespace hs::resolved {

/// Refuses (ConfigError, exit 2) a lattice of `nodes` that this machine's memory cannot hold, naming the keys that
/// sized it; a length key of 1 mm or more gets the micrometre hint (common/memory_budget.hpp).
void require_lattice_memory(const common::ConfigFile& file, const std::array<int, 3>& nodes,
                            std::initializer_list<common::SizingKey> keys);

}  // namespace hs::resolved
