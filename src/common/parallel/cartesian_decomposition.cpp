// SPDX-License-Identifier: MIT
// MPI Cartesian block decomposition of a global grid.
#include "common/parallel/cartesian_decomposition.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace hs::common {
namespace {

/// Offset and size of block `c` of `parts` when `n` nodes are split as evenly as possible.
std::array<int, 2> split(int n, int parts, int c) {
  const int base = n / parts;
  const int extra = n % parts;
  return {c * base + (c < extra ? c : extra), base + (c < extra ? 1 : 0)};
}

}  // namespace

CartesianDecomposition::CartesianDecomposition(const DecompositionSpec& spec, MPI_Comm comm) : spec_(spec) {
  int comm_size = 1;
  MPI_Comm_size(comm, &comm_size);
  dims_ = spec.ranks_per_axis;
  int fixed = 1;
  for (const int d : dims_) fixed *= d > 0 ? d : 1;
  if (comm_size % fixed != 0) {
    throw std::invalid_argument(fmt::format("ranks per axis ({}, {}, {}) do not divide the {} ranks", dims_[0], dims_[1],
                                            dims_[2], comm_size));
  }
  MPI_Dims_create(comm_size, 3, dims_.data());
  std::array<int, 3> periods{};
  for (int a = 0; a < 3; ++a) {
    periods[a] = spec.periodic[a] ? 1 : 0;
    if (spec.global_nodes[a] < dims_[a] * spec.ghost || spec.global_nodes[a] < 1) {
      throw std::invalid_argument(fmt::format("axis {}: {} nodes cannot be split over {} ranks with {} ghost layers",
                                              a, spec.global_nodes[a], dims_[a], spec.ghost));
    }
  }
  MPI_Cart_create(comm, 3, dims_.data(), periods.data(), 0, &cart_);
  MPI_Comm_rank(cart_, &rank_);
  MPI_Comm_size(cart_, &size_);
  MPI_Cart_coords(cart_, rank_, 3, coords_.data());
  layout_.ghost = spec.ghost;
  for (int a = 0; a < 3; ++a) {
    const auto [off, size] = split(spec.global_nodes[a], dims_[a], coords_[a]);
    offset_[a] = off;
    layout_.n[a] = size;
    MPI_Cart_shift(cart_, a, 1, &neighbours_[a][0], &neighbours_[a][1]);
  }
}

CartesianDecomposition::~CartesianDecomposition() {
  if (cart_ != MPI_COMM_NULL) MPI_Comm_free(&cart_);
}

std::array<std::array<int, 2>, 3> CartesianDecomposition::block_of(const std::array<int, 3>& coords) const {
  std::array<std::array<int, 2>, 3> r{};
  for (int a = 0; a < 3; ++a) r[a] = split(spec_.global_nodes[a], dims_[a], coords[a]);
  return r;
}

}  // namespace hs::common
