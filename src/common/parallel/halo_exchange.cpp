// SPDX-License-Identifier: MIT
// Ghost-layer exchange of structure-of-arrays fields on a Cartesian block decomposition.
#include "common/parallel/halo_exchange.hpp"

#include <numeric>

namespace hs::common {
namespace {

/// Ranges of the two axes other than `axis`: interior for axes not yet exchanged, ghost-inclusive for
/// axes exchanged before (x before y before z), so corners are filled by the later exchanges.
std::array<std::array<int, 2>, 3> slab_ranges(const BlockLayout& l, int axis, int first) {
  std::array<std::array<int, 2>, 3> r{};
  for (int a = 0; a < 3; ++a) {
    if (a == axis) {
      r[a] = {first, first + l.ghost};
    } else if (a < axis) {
      r[a] = {-l.ghost, l.n[a] + l.ghost};
    } else {
      r[a] = {0, l.n[a]};
    }
  }
  return r;
}

}  // namespace

HaloExchange::HaloExchange(const CartesianDecomposition& decomposition) : decomposition_(decomposition) {}

void HaloExchange::exchange(std::span<double> field, int components, std::size_t stride) {
  stride_ = stride == 0 ? decomposition_.layout().volume() : stride;
  std::vector<int> all(static_cast<std::size_t>(components));
  std::iota(all.begin(), all.end(), 0);
  for (int axis = 0; axis < 3; ++axis) exchange_axis(field, axis, all, all);
}

void HaloExchange::exchange(std::span<double> field,
                            const std::array<std::array<std::vector<int>, 2>, 3>& per_face, std::size_t stride) {
  stride_ = stride == 0 ? decomposition_.layout().volume() : stride;
  for (int axis = 0; axis < 3; ++axis) exchange_axis(field, axis, per_face[axis][0], per_face[axis][1]);
}

void HaloExchange::pack(std::span<const double> field, int axis, int first, const std::vector<int>& comps,
                        std::vector<double>& buf) const {
  const BlockLayout& l = decomposition_.layout();
  const auto r = slab_ranges(l, axis, first);
  buf.clear();
  for (const int c : comps) {
    const std::size_t base = static_cast<std::size_t>(c) * stride_;
    for (int z = r[2][0]; z < r[2][1]; ++z) {
      for (int y = r[1][0]; y < r[1][1]; ++y) {
        for (int x = r[0][0]; x < r[0][1]; ++x) buf.push_back(field[base + static_cast<std::size_t>(l.index(x, y, z))]);
      }
    }
  }
}

void HaloExchange::unpack(std::span<double> field, int axis, int first, const std::vector<int>& comps,
                          const std::vector<double>& buf) const {
  const BlockLayout& l = decomposition_.layout();
  const auto r = slab_ranges(l, axis, first);
  std::size_t k = 0;
  for (const int c : comps) {
    const std::size_t base = static_cast<std::size_t>(c) * stride_;
    for (int z = r[2][0]; z < r[2][1]; ++z) {
      for (int y = r[1][0]; y < r[1][1]; ++y) {
        for (int x = r[0][0]; x < r[0][1]; ++x) field[base + static_cast<std::size_t>(l.index(x, y, z))] = buf[k++];
      }
    }
  }
}

void HaloExchange::exchange_axis(std::span<double> field, int axis, const std::vector<int>& to_low,
                                 const std::vector<int>& to_high) {
  const BlockLayout& l = decomposition_.layout();
  const int low = decomposition_.neighbour(axis, 0);
  const int high = decomposition_.neighbour(axis, 1);
  const MPI_Comm comm = decomposition_.comm();
  const int g = l.ghost;
  const int n = l.n[axis];
  // Through the low face: my first interior layers go to the low neighbour's high ghosts.
  pack(field, axis, 0, to_low, send_low_);
  recv_high_.resize(send_low_.size());
  MPI_Sendrecv(send_low_.data(), static_cast<int>(send_low_.size()), MPI_DOUBLE, low, 2 * axis,
               recv_high_.data(), static_cast<int>(recv_high_.size()), MPI_DOUBLE, high, 2 * axis, comm,
               MPI_STATUS_IGNORE);
  if (high != MPI_PROC_NULL) unpack(field, axis, n, to_low, recv_high_);
  // Through the high face: my last interior layers go to the high neighbour's low ghosts.
  pack(field, axis, n - g, to_high, send_high_);
  recv_low_.resize(send_high_.size());
  MPI_Sendrecv(send_high_.data(), static_cast<int>(send_high_.size()), MPI_DOUBLE, high, 2 * axis + 1,
               recv_low_.data(), static_cast<int>(recv_low_.size()), MPI_DOUBLE, low, 2 * axis + 1, comm,
               MPI_STATUS_IGNORE);
  if (low != MPI_PROC_NULL) unpack(field, axis, -g, to_high, recv_low_);
}

}  // namespace hs::common
