// SPDX-License-Identifier: MIT
// The reverse halo exchange of the AA pattern: populations written into ghost nodes go to their owners.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"

namespace hs::resolved {

/// After an AA neighbour step, interior node x has written f*_i(x) into slot A[i][x + c_i]; where x + c_i is a
/// ghost node, that slot belongs to the rank (or, along a periodic axis with one rank, the block itself) that owns
/// the node. fold() sends it there, axis by axis in the reverse order of HaloExchange (z, then y including the x
/// ghosts, then x), so values written into edge and corner ghosts travel on to the interior of the diagonal
/// owner. Through the low face of axis a go the components with c_ia = -1, landing in the low neighbour's last
/// interior layer, whose slots of those components no local node wrote (their writers are beyond the face).
/// Ghosts on non-periodic global faces are left as they are (wall passes own them).
class AaGhostFold {
 public:
  AaGhostFold(const common::CartesianDecomposition& decomposition, std::size_t stride);

  /// `field`: the population buffer, component stride `stride`. Collective.
  void fold(std::span<double> field);

 private:
  void fold_axis(std::span<double> field, int axis);
  void copy_slab(std::span<double> field, int axis, int layer, const std::vector<int>& comps, std::vector<double>& buf,
                 bool to_buffer) const;

  const common::CartesianDecomposition& decomposition_;
  std::size_t stride_;
  std::array<std::array<std::vector<int>, 2>, 3> components_;   // [axis][side]: c_ia = -1 (low), +1 (high)
  std::vector<double> send_, recv_;
};

}  // namespace hs::resolved
