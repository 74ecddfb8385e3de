// SPDX-License-Identifier: MIT
#include "unresolved/cases/slab_gather.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace hs::unresolved {

int rank_of(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

Gathered gathered(const std::vector<double>& mine, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size == 1) return {mine, {static_cast<int>(mine.size())}};
  const int count = static_cast<int>(mine.size());
  const bool root = rank_of(comm) == 0;
  std::vector<int> counts(root ? static_cast<std::size_t>(size) : 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::vector<int> displs(counts.size(), 0);
  if (root) std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  std::vector<double> all(root ? static_cast<std::size_t>(displs.back() + counts.back()) : 0);
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm);
  return {std::move(all), std::move(counts)};
}

std::vector<double> whole_grid(const std::vector<double>& mine, const FvmGrid& g, int components, MPI_Comm comm) {
  if (g.slabs() == nullptr) return mine;
  const Gathered all = gathered(mine, comm);
  const std::vector<double> firsts = gathered({static_cast<double>(g.first_plane())}, comm).values;
  if (all.counts.empty()) return {};
  const auto& n = g.global_cells();
  const std::size_t per_plane = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(components);
  std::vector<double> whole(per_plane * static_cast<std::size_t>(n[2]));
  std::size_t from = 0;
  for (std::size_t r = 0; r < all.counts.size(); ++r) {
    const auto count = static_cast<std::size_t>(all.counts[r]);
    std::copy_n(all.values.begin() + static_cast<long>(from), count,
                whole.begin() + static_cast<long>(static_cast<std::size_t>(firsts[r]) * per_plane));
    from += count;
  }
  return whole;
}

}  // namespace hs::unresolved
