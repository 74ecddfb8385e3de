// SPDX-License-Identifier: MIT
// Dense placement of many cells by growth: shrunken cells placed at random, then moved and turned at random (hard
// overlap test on the real meshes) while they grow back to full size (issue #24).
#pragma once

#include <cstdint>
#include <vector>

#include "resolved/cases/placement_geometry.hpp"

namespace hs::resolved::placement {

struct PackingResult {
  std::vector<Pose> poses;   // the n cells (at `scale` of full size)
  double start_scale = 0.0;  // the size the random sequential addition placed them at
  double scale = 0.0;        // the size reached: 1 when complete
  long sweeps = 0;           // Monte Carlo sweeps (one trial move per cell)
  long attempts = 0;         // random tries of the start's addition
  [[nodiscard]] bool complete() const { return scale == 1.0; }
};

/// n cells placed by random sequential addition at a reduced size (from the size at which they fill a tenth of the
/// box, shrinking by 10 % until they fit), then grown back: each sweep tries one random translation and rotation per
/// cell (accepted when the cell stays clear of the walls, the gap and the other cells' insides, at the current size;
/// step sizes adapted to 30-50 % acceptance), then tries a larger size for all cells at once (accepted when every
/// test holds at it; the step doubles on success up to 0.05 and halves on failure down to 1e-5). Stops at full
/// size, or as jammed when the growth rate over the last 200 sweeps would not reach full size within `max_sweeps`.
/// Deterministic for a seed (std::mt19937_64).
[[nodiscard]] PackingResult grow_packing(const CellGeometry& g, long n, std::uint64_t seed, int attempts_per_cell,
                                         long max_sweeps);

}  // namespace hs::resolved::placement
