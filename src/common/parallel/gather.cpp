// SPDX-License-Identifier: MIT
// Collecting a decomposed field on rank 0.
#include "common/parallel/gather.hpp"

#include <stdexcept>

namespace hs::common {

std::vector<double> gather_to_root(const CartesianDecomposition& d, std::span<const double> local, int components) {
  const int size = d.size();
  const auto comps = static_cast<std::size_t>(components);
  if (local.size() != d.layout().interior_volume() * comps) throw std::invalid_argument("gather_to_root: wrong local size");
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
  const int mine = static_cast<int>(local.size());
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, d.comm());
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<double> all(d.rank() == 0 ? static_cast<std::size_t>(total) : 0);
  MPI_Gatherv(local.data(), mine, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, d.comm());
  if (d.rank() != 0) return {};
  const auto& g = d.global_nodes();
  std::vector<double> out(static_cast<std::size_t>(g[0]) * static_cast<std::size_t>(g[1]) *
                          static_cast<std::size_t>(g[2]) * comps);
  for (int r = 0; r < size; ++r) {
    std::array<int, 3> coords{};
    MPI_Cart_coords(d.comm(), r, 3, coords.data());
    const auto b = d.block_of(coords);
    std::size_t k = static_cast<std::size_t>(displs[static_cast<std::size_t>(r)]);
    for (int z = b[2][0]; z < b[2][0] + b[2][1]; ++z) {
      for (int y = b[1][0]; y < b[1][0] + b[1][1]; ++y) {
        for (int x = b[0][0]; x < b[0][0] + b[0][1]; ++x) {
          const std::size_t n = static_cast<std::size_t>(x) +
                                static_cast<std::size_t>(g[0]) * (static_cast<std::size_t>(y) + static_cast<std::size_t>(g[1]) * static_cast<std::size_t>(z));
          for (std::size_t c = 0; c < comps; ++c) out[n * comps + c] = all[k++];
        }
      }
    }
  }
  return out;
}

}  // namespace hs::common
