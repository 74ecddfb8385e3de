// SPDX-License-Identifier: MIT
// Seeded random placement of many cells at a target hematocrit, randomly oriented, without overlaps (issue #24).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

/// The box the cells fill: [lower, upper) along each axis; periodic axes wrap (a cell may straddle the face), along
/// the others every vertex must keep `wall_clearance_m` from the faces.
struct PlacementBox {
  common::Vec3 lower_m;
  common::Vec3 upper_m;
  std::array<bool, 3> periodic{};
};

struct PlacementSpec {
  double hematocrit = 0.0;        // target N V_cell / V_box
  double min_gap_m = 0.0;         // smallest distance between vertices of different cells
  double wall_clearance_m = 0.0;  // smallest distance of a vertex from a non-periodic face
  std::uint64_t seed = 1;
  int attempts_per_cell = 20000;  // random tries for one cell before random sequential addition gives up
  long max_packing_sweeps = 10000;  // Monte Carlo sweeps of the growth packing at most (it stops earlier when jammed)
};

enum class PlacementMethod { random_sequential_addition, growth_packing };

struct Placement {
  std::vector<std::vector<common::Vec3>> cells_m;   // each cell's vertices (the rest mesh turned and moved), unwrapped
  double hematocrit = 0.0;                          // N V_cell / V_box reached
  double cell_volume_m3 = 0.0;
  double box_volume_m3 = 0.0;
  long attempts = 0;                                // random tries in all
  PlacementMethod method = PlacementMethod::random_sequential_addition;
  long packing_sweeps = 0;                          // growth packing only: its Monte Carlo sweeps
  double packing_start_scale = 0.0;                 // and the size its cells started at
};

[[nodiscard]] inline const char* placement_method_name(PlacementMethod m) {
  return m == PlacementMethod::growth_packing ? "growth_packing" : "random_sequential_addition";
}

/// Thrown when the cells do not fit (the case reports it as a bad input, exit 2).
class PlacementImpossible : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// N = round(phi V_box / V_cell) copies of `rest` (any closed mesh; its centroid is its centre), each turned by a
/// uniformly random rotation (Shoemake 1992 quaternions) and moved to a uniformly random centre, accepted when
/// (random sequential addition): every vertex keeps the wall clearance; no vertex of another cell lies within
/// min_gap_m (minimum image across periodic faces); and no vertex of either lies inside the other (an inside/outside
/// voxel map of the rest mesh, 1/50 of its extent). The last test catches overlaps whose vertices are far apart
/// (a rim through a dimple). When a cell finds no place in attempts_per_cell tries, the growth packing
/// (cell_packing.hpp) places all N shrunken and grows them back to full size under the same tests. Either way the
/// cells end rigid copies of `rest` at full size. Deterministic for a seed (std::mt19937_64). Throws
/// PlacementImpossible saying what both reached, when the target is below half a cell in the box, and at once when
/// the N cells' volume exceeds the box's less the wall clearances.
[[nodiscard]] Placement place_cells(const TriangleMesh& rest, const PlacementBox& box, const PlacementSpec& spec);

/// Smallest distance between vertices of different cells (minimum image along periodic axes), O(N^2) (tests, reports).
[[nodiscard]] double min_intercell_distance_m(const std::vector<std::vector<common::Vec3>>& cells_m,
                                              const PlacementBox& box);

}  // namespace hs::resolved
