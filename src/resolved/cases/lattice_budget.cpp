// SPDX-License-Identifier: MIT
#include "resolved/cases/lattice_budget.hpp"

#include <vector>

#include <fmt/format.h>

#include "resolved/lbm/lattice_memory.hpp"

namespace hs::resolved {

void require_lattice_memory(const common::ConfigFile& file, const std::array<int, 3>& nodes,
                            std::initializer_list<common::SizingKey> keys) {
  const std::vector<common::SizingKey> sizing(keys);
  common::require_memory(file, {fmt::format("a lattice of {} x {} x {} nodes", nodes[0], nodes[1], nodes[2]),
                                lattice_memory_bytes(nodes)},
                         sizing);
}

}  // namespace hs::resolved
