// SPDX-License-Identifier: MIT
// A short-range repulsion between the membranes of different cells, found through a cell list (cost ~ N vertices).
#pragma once

#include <span>
#include <vector>

#include "common/vec3.hpp"

namespace hs::resolved {

struct CellContactSpec {
  double range_m = 0.0;        // d0: vertex pairs of different cells closer than this repel; 0 switches it off
  double stiffness_N_m = 0.0;  // k_c of F = k_c (d0 - r) along the pair's separation
  common::Vec3 period_m{};     // periodic box lengths (0: not periodic along that axis); the minimum image is used
};

struct CellContactReport {
  int pairs = 0;                  // vertex pairs that repelled
  double min_distance_m = 0.0;    // smallest inter-cell vertex distance found within d0 (d0 when none)
  double total_N = 0.0;           // sum of the pair forces' magnitudes
};

/// Adds F = k_c (d0 - r) r_hat to both vertices of every pair (i in cell a, j in cell b != a) with r = |x_i - x_j|
/// < d0, equal and opposite, so the cells' total momentum is unchanged. The same soft-contact penalty as the
/// membrane-wall repulsion (resolved/cases/wall_repulsion.hpp), standing in for the lubrication film the lattice
/// cannot resolve between two cells, as the cell-cell repulsion of HemoCell (Zavodszky et al. 2017, Front Physiol
/// 8:563) does. Pairs are found on a grid of d0-sized bins: the cost grows with the number of vertices, not its
/// square. `forces_N[c]` holds one force per vertex of `cells_m[c]`.
CellContactReport add_cell_contact_forces(const std::vector<std::span<const common::Vec3>>& cells_m,
                                          std::vector<std::vector<common::Vec3>>& forces_N,
                                          const CellContactSpec& spec);

}  // namespace hs::resolved
