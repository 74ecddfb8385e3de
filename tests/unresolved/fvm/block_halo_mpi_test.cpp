// SPDX-License-Identifier: MIT
// exchange_halo on z-slabs at np 1, 2 and 4: every ghost plane equals the plane of the whole grid it stands for, bit
// for bit, the whole grid's periodic ghosts coming from BlockField::fill_periodic (the one-rank reference); on a
// non-periodic axis the global faces' ghosts are left alone.
#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>

#include "common/parallel/cartesian_decomposition.hpp"
#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/block_halo.hpp"

namespace hs::unresolved {
namespace {

constexpr std::array<int, 3> kCells{5, 4, 12};   // 12 planes: 3 per rank at np 4
constexpr double kUntouched = -777.0;

/// A value that differs at every point of the whole grid, ghost rows along x and y included.
double value_at(int i, int j, int k) { return std::sin(1.0 + i) + 10.0 * std::cos(2.0 + j) + 100.0 * k; }

BlockField<double> whole_grid(bool periodic) {
  BlockField<double> g(kCells, kUntouched);
  for (int k = 0; k < kCells[2]; ++k) {
    for (int j = -1; j <= kCells[1] + 1; ++j) {
      for (int i = -1; i <= kCells[0] + 1; ++i) g(i, j, k) = value_at(i, j, k);
    }
  }
  if (periodic) g.fill_periodic(2, kCells[2]);
  return g;
}

void check_slabs(bool periodic) {
  const hs::common::CartesianDecomposition d({.global_nodes = kCells, .periodic = {false, false, periodic},
                                              .ranks_per_axis = {1, 1, 0}, .ghost = 2},
                                             MPI_COMM_WORLD);
  const int first = d.offset()[2];
  const int planes = d.layout().n[2];
  BlockField<double> local({kCells[0], kCells[1], planes}, kUntouched);
  for (int k = 0; k < planes; ++k) {
    for (int j = -1; j <= kCells[1] + 1; ++j) {
      for (int i = -1; i <= kCells[0] + 1; ++i) local(i, j, k) = value_at(i, j, first + k);
    }
  }
  exchange_halo(local, d, 2);

  const BlockField<double> whole = whole_grid(periodic);
  int mismatches = 0;
  for (const int k : {-1, planes, planes + 1}) {
    const int global = first + k;
    const bool outside = global < 0 || global > kCells[2] - 1;
    for (int j = -1; j <= kCells[1] + 1; ++j) {
      for (int i = -1; i <= kCells[0] + 1; ++i) {
        // Inside the whole grid: the plane it stands for. Beyond it: the periodic image, or untouched on a wall.
        const double expected = !outside ? whole(i, j, global) : periodic ? whole(i, j, global) : kUntouched;
        if (local(i, j, k) != expected) ++mismatches;
      }
    }
  }
  int all = 0;
  MPI_Allreduce(&mismatches, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(all, 0);
}

TEST(BlockHalo, PeriodicSlabsGetTheWholeGridsPlanesAndItsPeriodicImages) { check_slabs(true); }

TEST(BlockHalo, WallsKeepTheirGhostsForTheBoundaryConditions) { check_slabs(false); }

TEST(BlockHalo, ABlockOfOnePlaneIsRefusedOnEveryRank) {
  const hs::common::CartesianDecomposition d({.global_nodes = kCells, .periodic = {false, false, true},
                                              .ranks_per_axis = {1, 1, 0}, .ghost = 1},
                                             MPI_COMM_WORLD);
  BlockField<double> one_plane({kCells[0], kCells[1], 1}, 0.0);
  EXPECT_THROW(exchange_halo(one_plane, d, 2), std::invalid_argument);
}

}  // namespace
}  // namespace hs::unresolved
