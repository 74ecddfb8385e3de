// SPDX-License-Identifier: MIT
// The reverse halo exchange of the AA pattern.
#include "resolved/lbm/aa_ghost_fold.hpp"

#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

AaGhostFold::AaGhostFold(const common::CartesianDecomposition& decomposition, std::size_t stride)
    : decomposition_(decomposition), stride_(stride) {
  for (std::size_t a = 0; a < 3; ++a) {
    for (int i = 0; i < D3Q19::q; ++i) {
      const int ca = D3Q19::c[static_cast<std::size_t>(i)][a];
      if (ca == -1) components_[a][0].push_back(i);
      if (ca == 1) components_[a][1].push_back(i);
    }
  }
}

void AaGhostFold::fold(std::span<double> field) {
  for (int axis = 2; axis >= 0; --axis) fold_axis(field, axis);
}

/// Copies the one-node-thick slab at `layer` of `axis` between `field` and `buf`. Along the axes folded later
/// (lower index) the slab includes the ghosts, along those folded before (higher index) only the interior.
void AaGhostFold::copy_slab(std::span<double> field, int axis, int layer, const std::vector<int>& comps,
                            std::vector<double>& buf, bool to_buffer) const {
  const common::BlockLayout& l = decomposition_.layout();
  std::array<std::array<int, 2>, 3> r{};
  for (int a = 0; a < 3; ++a) {
    const auto aa = static_cast<std::size_t>(a);
    if (a == axis) {
      r[aa] = {layer, layer + 1};
    } else if (a < axis) {
      r[aa] = {-l.ghost, l.n[aa] + l.ghost};
    } else {
      r[aa] = {0, l.n[aa]};
    }
  }
  if (to_buffer) buf.clear();
  std::size_t k = 0;
  for (const int c : comps) {
    const std::size_t base = static_cast<std::size_t>(c) * stride_;
    for (int z = r[2][0]; z < r[2][1]; ++z) {
      for (int y = r[1][0]; y < r[1][1]; ++y) {
        for (int x = r[0][0]; x < r[0][1]; ++x) {
          double& slot = field[base + static_cast<std::size_t>(l.index(x, y, z))];
          if (to_buffer) {
            buf.push_back(slot);
          } else {
            slot = buf[k++];
          }
        }
      }
    }
  }
}

void AaGhostFold::fold_axis(std::span<double> field, int axis) {
  const common::BlockLayout& l = decomposition_.layout();
  const auto a = static_cast<std::size_t>(axis);
  const int low = decomposition_.neighbour(axis, 0);
  const int high = decomposition_.neighbour(axis, 1);
  const MPI_Comm comm = decomposition_.comm();
  const int n = l.n[a];
  constexpr int kTag = 40;   // apart from HaloExchange's tags 0..5
  // My low ghost layer goes to the low neighbour's last interior layer; I receive into mine from the high one.
  copy_slab(field, axis, -1, components_[a][0], send_, true);
  recv_.resize(send_.size());
  MPI_Sendrecv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, low, kTag + 2 * axis, recv_.data(),
               static_cast<int>(recv_.size()), MPI_DOUBLE, high, kTag + 2 * axis, comm, MPI_STATUS_IGNORE);
  if (high != MPI_PROC_NULL) copy_slab(field, axis, n - 1, components_[a][0], recv_, false);
  // My high ghost layer goes to the high neighbour's first interior layer.
  copy_slab(field, axis, n, components_[a][1], send_, true);
  recv_.resize(send_.size());
  MPI_Sendrecv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, high, kTag + 2 * axis + 1, recv_.data(),
               static_cast<int>(recv_.size()), MPI_DOUBLE, low, kTag + 2 * axis + 1, comm, MPI_STATUS_IGNORE);
  if (low != MPI_PROC_NULL) copy_slab(field, axis, 0, components_[a][1], recv_, false);
}

}  // namespace hs::resolved
