// SPDX-License-Identifier: MIT
// The ghost planes of a BlockField filled from the neighbouring ranks' blocks: the distributed form of
// BlockField::fill_periodic, for an FVM grid split into slabs (issue #28, docs/cfd-dem.md "Distributed CFD-DEM").
#pragma once

#include <mpi.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"
#include "unresolved/fvm/block_field.hpp"

namespace hs::unresolved {

/// Fills the ghost planes of `f` along `axis` from the blocks of the neighbouring ranks: plane -1 from the low
/// neighbour's last plane, planes n and n + 1 from the high neighbour's first two (a staggered grid's face n is the
/// next block's face 0), every point of the plane including its ghosts along the other axes. With one rank along a
/// periodic axis the block exchanges with itself through MPI, so one rank runs the same code and gets exactly
/// fill_periodic(axis, n). Ghost planes on a non-periodic global face are left to the boundary conditions.
/// The decomposition must split only `axis` (slabs: every plane the same size) and every block must hold at least
/// two planes. Collective over the decomposition's communicator.
template <typename T>
void exchange_halo(BlockField<T>& f, const hs::common::CartesianDecomposition& d, int axis) {
  static_assert(std::is_trivially_copyable_v<T>, "the halo is sent as bytes");
  for (int a = 0; a < 3; ++a) {
    if (a != axis && d.ranks_per_axis()[static_cast<std::size_t>(a)] != 1) {
      throw std::invalid_argument("exchange_halo: the grid must be split along axis " + std::to_string(axis) + " only");
    }
  }
  const int n = f.cells()[static_cast<std::size_t>(axis)];
  int thinnest = 0;
  MPI_Allreduce(&n, &thinnest, 1, MPI_INT, MPI_MIN, d.comm());
  if (thinnest < 2) throw std::invalid_argument("exchange_halo: every block needs at least two planes along the split axis");

  std::vector<T> send, receive;
  const auto pack = [&](int plane) { f.for_each_in_plane(axis, plane, [&](std::size_t i) { send.push_back(f[i]); }); };
  const auto unpack = [&](int plane, std::size_t& from) {
    f.for_each_in_plane(axis, plane, [&](std::size_t i) { f[i] = receive[from++]; });
  };
  const auto swap = [&](int to, int from_rank, int tag) {
    receive.resize(send.size());
    const auto bytes = static_cast<int>(send.size() * sizeof(T));
    MPI_Sendrecv(send.data(), bytes, MPI_BYTE, to, tag, receive.data(), bytes, MPI_BYTE, from_rank, tag, d.comm(),
                 MPI_STATUS_IGNORE);
  };
  const int low = d.neighbour(axis, 0);
  const int high = d.neighbour(axis, 1);
  // The last plane goes up: it is the high neighbour's plane -1.
  send.clear();
  pack(n - 1);
  swap(high, low, 0);
  std::size_t at = 0;
  if (low != MPI_PROC_NULL) unpack(-1, at);
  // The first two planes go down: they are the low neighbour's planes n and n + 1.
  send.clear();
  pack(0);
  pack(1);
  swap(low, high, 1);
  at = 0;
  if (high != MPI_PROC_NULL) {
    unpack(n, at);
    unpack(n + 1, at);
  }
}

}  // namespace hs::unresolved
