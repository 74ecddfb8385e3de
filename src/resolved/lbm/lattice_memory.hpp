// SPDX-License-Identifier: MIT
// What a FluidLattice of a given size allocates, for the cases' memory check before they build one.
#pragma once

#include <array>

#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

/// Bytes of a D3Q19 lattice of `nodes` (global): two population sets of 19 doubles (the two-lattice kernel; AA needs
/// one, so this is an upper bound there), the force field (3 doubles), the flags, and the macroscopic arrays a VTK
/// frame gathers (rho and u: 4 doubles). Ghost layers and wall links add a few per cent, not counted.
[[nodiscard]] inline double lattice_memory_bytes(const std::array<int, 3>& nodes) {
  const double count = static_cast<double>(nodes[0]) * nodes[1] * nodes[2];
  constexpr double per_node = (2.0 * D3Q19::q + 3.0 + 4.0) * sizeof(double) + 1.0;
  return count * per_node;
}

}  // namespace hs::resolved
