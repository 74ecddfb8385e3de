// SPDX-License-Identifier: MIT
// Cartesian decomposition, halo exchange (ghost faces, edges and corners), gather and reductions, under MPI.
#include <gtest/gtest.h>
#include <mpi.h>

#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"
#include "common/parallel/gather.hpp"
#include "common/parallel/halo_exchange.hpp"
#include "common/parallel/reductions.hpp"

namespace hs::common {
namespace {

constexpr double kUntouched = -1.0;

double value(int c, int x, int y, int z) { return 1000.0 * c + x + 10.0 * y + 100.0 * z; }

/// Fills the interior with value(c, global x, y, z) and the ghosts with kUntouched, exchanges, and checks every
/// ghost: wrapped interior values along periodic axes, untouched beyond non-periodic global faces.
void check_exchange(const std::array<bool, 3>& periodic) {
  const std::array<int, 3> global{5, 4, 6};
  const CartesianDecomposition d(DecompositionSpec{.global_nodes = global, .periodic = periodic, .ranks_per_axis = {},
                                                   .ghost = 1},
                                 MPI_COMM_WORLD);
  const BlockLayout& l = d.layout();
  constexpr int comps = 3;
  std::vector<double> field(comps * l.volume(), kUntouched);
  const auto& off = d.offset();
  for (int c = 0; c < comps; ++c) {
    for (int z = 0; z < l.n[2]; ++z) {
      for (int y = 0; y < l.n[1]; ++y) {
        for (int x = 0; x < l.n[0]; ++x) {
          field[static_cast<std::size_t>(c) * l.volume() + static_cast<std::size_t>(l.index(x, y, z))] =
              value(c, x + off[0], y + off[1], z + off[2]);
        }
      }
    }
  }
  HaloExchange halo(d);
  halo.exchange(field, comps);
  for (int c = 0; c < comps; ++c) {
    for (int z = -1; z <= l.n[2]; ++z) {
      for (int y = -1; y <= l.n[1]; ++y) {
        for (int x = -1; x <= l.n[0]; ++x) {
          std::array<int, 3> g{x + off[0], y + off[1], z + off[2]};
          bool outside = false;
          for (std::size_t a = 0; a < 3; ++a) {
            if (periodic[a]) g[a] = (g[a] + global[a]) % global[a];
            outside = outside || g[a] < 0 || g[a] >= global[a];
          }
          const double got = field[static_cast<std::size_t>(c) * l.volume() + static_cast<std::size_t>(l.index(x, y, z))];
          ASSERT_EQ(got, outside ? kUntouched : value(c, g[0], g[1], g[2])) << x << " " << y << " " << z;
        }
      }
    }
  }
}

TEST(HaloExchange, PeriodicAxesFillFacesEdgesAndCorners) { check_exchange({true, true, true}); }
TEST(HaloExchange, NonPeriodicFacesAreLeftToBoundaryConditions) { check_exchange({false, true, false}); }

TEST(Parallel, GatherAndReductions) {
  const CartesianDecomposition d(DecompositionSpec{.global_nodes = {3, 4, 5}, .periodic = {}, .ranks_per_axis = {}, .ghost = 1},
                                 MPI_COMM_WORLD);
  const auto& l = d.layout();
  std::vector<double> local;
  for (int z = 0; z < l.n[2]; ++z) {
    for (int y = 0; y < l.n[1]; ++y) {
      for (int x = 0; x < l.n[0]; ++x) local.push_back(value(0, x + d.offset()[0], y + d.offset()[1], z + d.offset()[2]));
    }
  }
  const auto all = gather_to_root(d, local, 1);
  if (d.rank() == 0) {
    ASSERT_EQ(all.size(), 60u);
    std::size_t k = 0;
    for (int z = 0; z < 5; ++z) {
      for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 3; ++x) EXPECT_EQ(all[k++], value(0, x, y, z));
      }
    }
  }
  EXPECT_EQ(global_sum(1.0, d.comm()), static_cast<double>(d.size()));
  EXPECT_EQ(global_sum(2L, d.comm()), 2L * d.size());
  EXPECT_EQ(global_max(static_cast<double>(d.rank()), d.comm()), d.size() - 1.0);
  EXPECT_EQ(global_min(static_cast<double>(d.rank()), d.comm()), 0.0);
}

}  // namespace
}  // namespace hs::common
