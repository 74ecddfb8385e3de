// SPDX-License-Identifier: MIT
// The ghost-layer passes of the AA pattern: fill before neighbour steps, fold (reverse exchange) after them.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"

namespace hs::resolved {

/// Ghost layers of the single AA buffer (aa_stream_collide.hpp). Along an axis whose neighbour is another rank the
/// slabs travel by MPI; along a periodic axis with one rank they are copied directly, in parallel (no buffers).
///
/// fill() (swapped layout, before a neighbour step): the neighbour step at x reads A[opp(i)][x - c_i], so the high
/// ghost of axis a needs the slots with c_a = +1 of the high neighbour's first interior layer, the low ghost those
/// with c_a = -1 of the low neighbour's last one. Axis by axis, x then y then z, each slab including the ghosts of
/// the axes done before, so edge and corner ghosts are filled (as common::HaloExchange).
///
/// fold() (natural layout, after a neighbour step): interior node x has written f*_i(x) into A[i][x + c_i]; where
/// x + c_i is a ghost, the slot belongs to the node's owner. Axis by axis in reverse order (z, y including the
/// x ghosts, then x), the low ghost's slots with c_a = -1 go to the low neighbour's last interior layer (no node
/// there wrote them: their writers are beyond the face), the high ghost's slots with c_a = +1 to the high
/// neighbour's first. Values written into edge and corner ghosts travel on to the diagonal owner.
///
/// Ghosts on non-periodic global faces are left as they are (wall passes own them).
class AaHalo {
 public:
  /// `skip_x`: leave the x ghosts alone (the kernel wraps x itself, AaStreamCollideArgs::wrap_x).
  AaHalo(const common::CartesianDecomposition& decomposition, std::size_t stride, bool skip_x);

  /// `field`: the population buffer, component stride `stride`. Both collective.
  void fill(std::span<double> field);
  void fold(std::span<double> field);

 private:
  /// Moves the slab at `from` (layer along `axis`) to the neighbour's slab at `to`, components `comps`, sending to
  /// neighbour(axis, side) and receiving from the opposite one.
  void transfer(std::span<double> field, int axis, int side, int from, int to, const std::vector<int>& comps);
  void copy_slab(std::span<double> field, int axis, int layer, const std::vector<int>& comps, std::vector<double>& buf,
                 bool to_buffer) const;
  void copy_layer(std::span<double> field, int axis, int from, int to, const std::vector<int>& comps) const;
  [[nodiscard]] std::array<std::array<int, 2>, 3> slab_ranges(int axis, int layer) const;

  const common::CartesianDecomposition& decomposition_;
  std::size_t stride_;
  bool skip_x_;
  std::array<std::array<std::vector<int>, 2>, 3> components_;   // [axis][side]: c_ia = -1 (low), +1 (high)
  std::vector<double> send_, recv_;
};

}  // namespace hs::resolved
