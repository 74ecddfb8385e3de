// SPDX-License-Identifier: MIT
// Gathers on rank 0 what the z-slabs of a distributed run hold: values rank after rank, and cell fields as the whole
// grid's, so that an output file is the same on any rank count.
#pragma once

#include <vector>

#include <mpi.h>

#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {

/// This process's rank in `comm`.
[[nodiscard]] int rank_of(MPI_Comm comm);

/// Every rank's values on rank 0, rank after rank, with each rank's count (both empty on the other ranks).
struct Gathered {
  std::vector<double> values;
  std::vector<int> counts;
};
[[nodiscard]] Gathered gathered(const std::vector<double>& mine, MPI_Comm comm);

/// A cell field of the block (x fastest, z slowest, `components` values per cell) as the whole grid's on rank 0:
/// each slab's planes where its first plane is (empty on the other ranks; `mine` itself without slabs).
[[nodiscard]] std::vector<double> whole_grid(const std::vector<double>& mine, const FvmGrid& g, int components,
                                             MPI_Comm comm);

}  // namespace hs::unresolved
