// SPDX-License-Identifier: MIT
// For the distributed linear-solver tests: a box's z-slabs as each rank's row range (uneven on purpose), a whole
// matrix's rows for one rank, and vectors split and gathered in rank order.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <vector>

#include "unresolved/fvm/csr_matrix.hpp"

namespace hs::unresolved::distributed_rows {

struct RankRows {
  int first = 0;
  int count = 0;
};

/// This rank's z-planes of an n^3 box as a row range: every rank but the last one plane short of an even split.
inline RankRows my_rows(int n) {
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const auto first_plane = [&](int r) {
    if (r == 0) return 0;
    if (r == size) return n;
    return std::max(1, r * n / size - 1);
  };
  return {first_plane(rank) * n * n, (first_plane(rank + 1) - first_plane(rank)) * n * n};
}

/// Rows [first, first + count) of a whole matrix, with their global column indices.
inline CsrMatrix rows_of(const CsrMatrix& whole, RankRows mine) {
  CsrMatrix a;
  a.rows = mine.count;
  a.first_row = mine.first;
  a.row_ptr.push_back(0);
  for (int r = mine.first; r < mine.first + mine.count; ++r) {
    for (int q = whole.row_ptr[static_cast<std::size_t>(r)]; q < whole.row_ptr[static_cast<std::size_t>(r) + 1]; ++q) {
      a.cols.push_back(whole.cols[static_cast<std::size_t>(q)]);
      a.values.push_back(whole.values[static_cast<std::size_t>(q)]);
    }
    a.row_ptr.push_back(static_cast<int>(a.cols.size()));
  }
  return a;
}

/// Every rank's part of a distributed vector, put together in row order on every rank.
inline std::vector<double> gathered(const std::vector<double>& part) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int mine = static_cast<int>(part.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size), 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < size; ++r) offsets[static_cast<std::size_t>(r)] = offsets[static_cast<std::size_t>(r) - 1] + counts[static_cast<std::size_t>(r) - 1];
  std::vector<double> whole(static_cast<std::size_t>(offsets.back() + counts.back()));
  MPI_Allgatherv(part.data(), mine, MPI_DOUBLE, whole.data(), counts.data(), offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  return whole;
}

inline std::vector<double> part_of(const std::vector<double>& whole, RankRows mine) {
  return {whole.begin() + mine.first, whole.begin() + mine.first + mine.count};
}

}  // namespace hs::unresolved::distributed_rows
