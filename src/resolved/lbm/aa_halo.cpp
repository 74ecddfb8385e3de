// SPDX-License-Identifier: MIT
// The ghost-layer passes of the AA pattern.
#include "resolved/lbm/aa_halo.hpp"

#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {
namespace {

constexpr int kTag = 40;   // apart from common::HaloExchange's tags 0..5
/// Slabs below this many values are copied by one thread: a parallel region costs more than the copy.
constexpr std::size_t kMinValuesForThreads = 16384;

}  // namespace

AaHalo::AaHalo(const common::CartesianDecomposition& decomposition, std::size_t stride, bool skip_x)
    : decomposition_(decomposition), stride_(stride), skip_x_(skip_x) {
  for (std::size_t a = 0; a < 3; ++a) {
    for (int i = 0; i < D3Q19::q; ++i) {
      const int ca = D3Q19::c[static_cast<std::size_t>(i)][a];
      if (ca == -1) components_[a][0].push_back(i);
      if (ca == 1) components_[a][1].push_back(i);
    }
  }
}

void AaHalo::fill(std::span<double> field) {
  const auto& l = decomposition_.layout();
  for (int axis = skip_x_ ? 1 : 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    // My first interior layer's c_a = +1 slots to the low neighbour's high ghost, my last one's c_a = -1 slots to
    // the high neighbour's low ghost.
    transfer(field, axis, 0, 0, l.n[a], components_[a][1]);
    transfer(field, axis, 1, l.n[a] - 1, -1, components_[a][0]);
  }
}

void AaHalo::fold(std::span<double> field) {
  const auto& l = decomposition_.layout();
  for (int axis = 2; axis >= (skip_x_ ? 1 : 0); --axis) {
    const auto a = static_cast<std::size_t>(axis);
    transfer(field, axis, 0, -1, l.n[a] - 1, components_[a][0]);
    transfer(field, axis, 1, l.n[a], 0, components_[a][1]);
  }
}

/// Along the axes handled after `axis` (fill: higher index; fold: lower index, as it runs backwards) the slab is
/// interior only, along the others ghost-inclusive; for fill that is x < y < z, for fold z > y > x: in both cases
/// the lower axes are ghost-inclusive.
std::array<std::array<int, 2>, 3> AaHalo::slab_ranges(int axis, int layer) const {
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
  return r;
}

void AaHalo::transfer(std::span<double> field, int axis, int side, int from, int to, const std::vector<int>& comps) {
  const int dest = decomposition_.neighbour(axis, side);
  const int source = decomposition_.neighbour(axis, 1 - side);
  if (dest == MPI_PROC_NULL && source == MPI_PROC_NULL) return;
  if (dest == decomposition_.rank() && source == decomposition_.rank()) {   // periodic axis with one rank
    copy_layer(field, axis, from, to, comps);
    return;
  }
  copy_slab(field, axis, from, comps, send_, true);
  recv_.resize(send_.size());
  const int tag = kTag + 2 * axis + side;
  MPI_Sendrecv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, dest, tag, recv_.data(),
               static_cast<int>(recv_.size()), MPI_DOUBLE, source, tag, decomposition_.comm(), MPI_STATUS_IGNORE);
  if (source != MPI_PROC_NULL) copy_slab(field, axis, to, comps, recv_, false);
}

/// Copies the one-node-thick slab at `layer` of `axis` between `field` and `buf`.
void AaHalo::copy_slab(std::span<double> field, int axis, int layer, const std::vector<int>& comps,
                       std::vector<double>& buf, bool to_buffer) const {
  const common::BlockLayout& l = decomposition_.layout();
  const auto r = slab_ranges(axis, layer);
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

/// The same slab move within one block: layer `from` to layer `to` of `axis`, parallel over components and z.
void AaHalo::copy_layer(std::span<double> field, int axis, int from, int to, const std::vector<int>& comps) const {
  const common::BlockLayout& l = decomposition_.layout();
  const auto r = slab_ranges(axis, from);
  std::array<int, 3> shift{};
  shift[static_cast<std::size_t>(axis)] = to - from;
  const std::ptrdiff_t delta = l.offset(shift[0], shift[1], shift[2]);
  const auto nc = static_cast<int>(comps.size());
  const int nz = r[2][1] - r[2][0];
  const std::size_t values = comps.size() * static_cast<std::size_t>(nz) * static_cast<std::size_t>(r[1][1] - r[1][0]) *
                             static_cast<std::size_t>(r[0][1] - r[0][0]);
  double* f = field.data();
#pragma omp parallel for collapse(2) schedule(static) if (values >= kMinValuesForThreads)
  for (int k = 0; k < nc; ++k) {
    for (int dz = 0; dz < nz; ++dz) {
      const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(comps[static_cast<std::size_t>(k)]) *
                                  static_cast<std::ptrdiff_t>(stride_);
      const int z = r[2][0] + dz;
      for (int y = r[1][0]; y < r[1][1]; ++y) {
        const std::ptrdiff_t row = base + l.index(r[0][0], y, z);
        for (int x = 0; x < r[0][1] - r[0][0]; ++x) f[row + delta + x] = f[row + x];
      }
    }
  }
}

}  // namespace hs::resolved
