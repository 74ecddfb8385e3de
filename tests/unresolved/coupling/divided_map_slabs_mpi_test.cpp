// SPDX-License-Identifier: MIT
// The divided particle-to-grid map on z-slabs (issue #28 step 4) against one rank holding the whole grid and every
// particle: each block's void fraction and marker sums must be that rank's, sliced, bit for bit, because every cell
// adds its markers in (id, marker) order at any rank count. Run at np 1, 2 and 4 (oversubscribed).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "common/geometry/tube.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "unresolved/coupling/divided_void_fraction.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

// A tilted tube narrower than its box (every plane cuts the wall differently, so markers are lumped off the wall in
// each block differently): 10 cells of 3 um across, 20 planes (5 a block at np 4: 15 um, more than the ghost width).
constexpr double kBox = 30e-6;
constexpr double kLength = 60e-6;
constexpr double kDx = 3e-6;
constexpr Vec3 kStart{-3e-6, -1e-6, 0.0};
constexpr Vec3 kEnd{3e-6, 2e-6, kLength};
constexpr double kTubeRadius = 12e-6;
// Sphere radii 2 to 4.5 um: a marker (at up to 0.9 r from the centre) reaches up to two planes away.
constexpr double kLargestRadius = 4.5e-6;
constexpr int kParticles = 400;   // they overlap (Ht ~2): only the deposit is tested, no contacts

hs::common::Tube tube() { return hs::common::Tube({.start_m = kStart, .end_m = kEnd, .radius_m = kTubeRadius}); }

FvmGridSpec spec(bool periodic) {
  const double r = 0.5 * kBox;
  FvmGridSpec s{.box_m = {{-r, -r, 0.0}, {r, r, kLength}}, .dx_m = kDx, .sides = {}};
  if (periodic) {
    s.sides[4].type = SideType::periodic;
    s.sides[5].type = SideType::periodic;
  }
  return s;   // else walls at both ends: markers beyond them are lumped onto the centre's cell
}

/// The spheres (the same on every rank): ids shuffled against the order of placement, so neither a block's store nor
/// the whole one is in id order.
std::vector<ParticleState> spheres(bool periodic) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::int64_t> ids(kParticles);
  std::iota(ids.begin(), ids.end(), 100);
  std::shuffle(ids.begin(), ids.end(), rng);
  std::vector<ParticleState> out;
  while (out.size() < kParticles) {
    const double radius = 2e-6 + (kLargestRadius - 2e-6) * u(rng);
    // Open ends: the centre stays in the box (markers may not); periodic: anywhere, the seam included.
    const double margin = periodic ? 0.0 : 0.6 * kDx;
    const double z = margin + (kLength - 2.0 * margin) * u(rng);
    const Vec3 axis = kStart + (z / kLength) * (kEnd - kStart);
    const double angle = 2.0 * std::numbers::pi * u(rng);
    const double rho = (kTubeRadius - 0.5 * radius) * std::sqrt(u(rng));   // markers reach into the wall's cells
    const Vec3 x{axis.x + rho * std::cos(angle), axis.y + rho * std::sin(angle), z};
    out.push_back({.position_m = x, .velocity_m_s = {u(rng) - 0.5, u(rng) - 0.5, u(rng)}, .angular_velocity_rad_s = {},
                   .radius_m = radius, .mass_kg = 1.0, .id = ids[out.size()]});
  }
  return out;
}

/// A particle drifts after the rebuild that gave it its owner (up to half a skin): its centre may sit in a neighbour's
/// plane, across the periodic seam too. Here: up to 0.4 dx either way, not out of the open tube's box.
Vec3 drifted(const ParticleState& p, bool periodic) {
  const double dz = 0.4 * kDx * std::sin(static_cast<double>(p.id));
  Vec3 x = p.position_m;
  x.z = periodic ? x.z + dz : std::clamp(x.z + dz, 0.1 * kDx, kLength - 0.1 * kDx);
  return x;
}

struct Sums {
  BlockField<double> eps;
  BlockField<Vec3> velocity;   // sum of (velocity / 29) over a cell's markers
  BlockField<double> markers;  // markers in the cell
  double lost_m3 = 0.0;
};

Sums deposit(const FvmGrid& grid, const ParticleStore& particles) {
  DividedMap map(grid);
  map.locate(particles);
  Sums s{.eps = BlockField<double>(grid.cells(), 1.0), .velocity = BlockField<Vec3>(grid.cells(), Vec3{}),
         .markers = BlockField<double>(grid.cells(), 0.0)};
  s.lost_m3 = map.void_fraction(particles, 0.1, s.eps);
  map.for_each_cell([&](std::size_t c, std::size_t i, int markers) {
    s.velocity[c] += (static_cast<double>(markers) / kMarkersPerSphere) *
                     Vec3{particles.velocity_m_s()[0][i], particles.velocity_m_s()[1][i], particles.velocity_m_s()[2][i]};
    s.markers[c] += markers;
  });
  return s;
}

void expect_one_rank_sliced(bool periodic) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const hs::common::Tube shape = tube();
  const FvmGridSpec s = spec(periodic);
  const FvmGrid whole(shape, s);
  const hs::common::CartesianDecomposition decomposition(
      {.global_nodes = whole.cells(), .periodic = {false, false, periodic}, .ranks_per_axis = {1, 1, 0}, .ghost = 2},
      MPI_COMM_WORLD);
  const FvmGrid block(shape, s, &decomposition);
  const Domain domain{.box = s.box_m, .periodic = {false, false, periodic}};
  DemSlabs slabs(decomposition, domain, kDx);

  const std::vector<ParticleState> all = spheres(periodic);
  ParticleStore every;   // one rank holding every particle, drifted
  ParticleStore mine;    // this slab's: owned by the place at the last rebuild, then drifted, plus the ghosts
  for (ParticleState p : all) {
    const bool here = p.position_m.z >= slabs.lo_m() && p.position_m.z < slabs.hi_m();
    p.position_m = drifted(p, periodic);
    (void)every.add(p);
    if (here) (void)mine.add(p);
  }
  slabs.exchange_ghosts(mine, 2.0 * kLargestRadius);   // the DEM's cut-off is at least a diameter
  const Sums one = deposit(whole, every);
  const Sums many = deposit(block, mine);

  const int first = block.first_plane();
  const auto& n = block.cells();
  int differ = 0;
  double markers = 0.0;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t b = many.eps.index(i, j, k);
        const std::size_t w = one.eps.index(i, j, k + first);
        differ += many.eps[b] == one.eps[w] ? 0 : 1;
        for (int a = 0; a < 3; ++a) differ += many.velocity[b][a] == one.velocity[w][a] ? 0 : 1;
        differ += many.markers[b] == one.markers[w] ? 0 : 1;
        markers += many.markers[b];
      }
    }
  }
  int differ_all = 0;
  double markers_all = 0.0;
  double lost_all = 0.0;
  MPI_Allreduce(&differ, &differ_all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&markers, &markers_all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&many.lost_m3, &lost_all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  long ghosts = static_cast<long>(mine.n_ghost());
  long ghosts_all = 0;
  MPI_Allreduce(&ghosts, &ghosts_all, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  std::printf("divided map on %d slab(s), %s tube: %ld remote ghosts, %d cell values differ from one rank's, "
              "lost volume %.6e vs %.6e m^3\n", size, periodic ? "periodic" : "walled", ghosts_all, differ_all, lost_all,
              one.lost_m3);
  EXPECT_EQ(differ_all, 0);   // the same terms in the same order: the same bits
  EXPECT_EQ(markers_all, static_cast<double>(kMarkersPerSphere * kParticles)) << "a marker added twice or nowhere";
  // The clipped volume is summed per block and then over the blocks: the same terms, associated differently.
  EXPECT_NEAR(lost_all, one.lost_m3, 1e-12 * one.lost_m3);
  EXPECT_GT(one.lost_m3, 0.0) << "no cell was clipped: the test would not see the clip";
}

TEST(DividedMapOnSlabs, PeriodicTubeIsOneRanksSliced) { expect_one_rank_sliced(true); }

TEST(DividedMapOnSlabs, WalledTubeIsOneRanksSliced) { expect_one_rank_sliced(false); }

}  // namespace
}  // namespace hs::unresolved
