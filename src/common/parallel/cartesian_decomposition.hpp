// SPDX-License-Identifier: MIT
// MPI Cartesian block decomposition of a global grid; one rank runs the very same code path.
#pragma once

#include <array>

#include <mpi.h>

#include "common/parallel/block_layout.hpp"

namespace hs::common {

struct DecompositionSpec {
  std::array<int, 3> global_nodes{};          // nodes of the whole grid per axis
  std::array<bool, 3> periodic{};             // periodic flag per axis
  std::array<int, 3> ranks_per_axis{};        // 0 = let MPI_Dims_create choose
  int ghost = 1;                              // ghost layers per side
};

/// Splits the global grid into one block per rank (MPI_Cart_create) and knows the neighbours along each axis.
/// Blocks differ in size by at most one node per axis. Neighbours across a non-periodic global face are
/// MPI_PROC_NULL; with one rank along a periodic axis, the neighbour is the rank itself (self-exchange).
class CartesianDecomposition {
 public:
  /// Collective over `comm`. Throws std::invalid_argument if an axis has fewer nodes than ranks * ghost.
  CartesianDecomposition(const DecompositionSpec& spec, MPI_Comm comm);
  ~CartesianDecomposition();
  CartesianDecomposition(const CartesianDecomposition&) = delete;
  CartesianDecomposition& operator=(const CartesianDecomposition&) = delete;

  [[nodiscard]] MPI_Comm comm() const { return cart_; }
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }
  [[nodiscard]] const BlockLayout& layout() const { return layout_; }
  [[nodiscard]] const std::array<int, 3>& global_nodes() const { return spec_.global_nodes; }
  [[nodiscard]] const std::array<bool, 3>& periodic() const { return spec_.periodic; }
  [[nodiscard]] const std::array<int, 3>& ranks_per_axis() const { return dims_; }
  /// Global index of local node 0 along each axis.
  [[nodiscard]] const std::array<int, 3>& offset() const { return offset_; }
  /// Neighbour rank along `axis` on side 0 (low) or 1 (high); MPI_PROC_NULL at a non-periodic global face.
  [[nodiscard]] int neighbour(int axis, int side) const { return neighbours_[axis][side]; }
  /// True when the block's face (axis, side) lies on a non-periodic global boundary.
  [[nodiscard]] bool on_global_face(int axis, int side) const { return neighbour(axis, side) == MPI_PROC_NULL; }
  /// Block extent of the rank with Cartesian coordinates `coords`: {offset, size} per axis.
  [[nodiscard]] std::array<std::array<int, 2>, 3> block_of(const std::array<int, 3>& coords) const;

 private:
  DecompositionSpec spec_;
  MPI_Comm cart_ = MPI_COMM_NULL;
  int rank_ = 0;
  int size_ = 1;
  std::array<int, 3> dims_{};
  std::array<int, 3> coords_{};
  std::array<int, 3> offset_{};
  std::array<std::array<int, 2>, 3> neighbours_{};
  BlockLayout layout_;
};

}  // namespace hs::common
