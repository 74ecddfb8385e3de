// SPDX-License-Identifier: MIT
// The linked-cell half Verlet list against an O(N^2) search with minimum-image distances.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

using PairSet = std::set<std::pair<std::int64_t, std::int64_t>>;

/// Random polydisperse-free gas of n spheres in a cube (overlaps allowed: only the search is tested).
DemSystem random_particles(bool periodic, int n, std::uint64_t seed) {
  ParticleParams p = test::rbcpack_params();
  const double half = 6.0 * p.diameter_m;
  DemSystem dem({.params = p, .domain = test::cube(half, periodic), .time_step_s = 1e-7}, nullptr);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-half, half);
  std::uniform_real_distribution<double> uv(-5e-2, 5e-2);
  for (int i = 0; i < n; ++i) dem.add_particle({u(rng), u(rng), u(rng)}, {uv(rng), uv(rng), uv(rng)});
  return dem;
}

/// Pairs of owned ids with centre distance (minimum image along periodic axes) below r_i + r_j + extra.
PairSet brute_force(const DemSystem& dem, double extra_m) {
  const auto& p = dem.particles();
  const auto& d = dem.domain();
  PairSet out;
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    for (std::size_t j = i + 1; j < p.n_owned(); ++j) {
      double r2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        double dx = p.position_m()[a][i] - p.position_m()[a][j];
        if (d.periodic[a]) dx -= d.length_m(a) * std::round(dx / d.length_m(a));
        r2 += dx * dx;
      }
      const double rc = p.radius_m()[i] + p.radius_m()[j] + extra_m;
      if (r2 < rc * rc) out.insert(std::minmax(p.id()[i], p.id()[j]));
    }
  }
  return out;
}

/// Pairs in the list whose current distance is below r_i + r_j + extra (all of them for extra = skin at a build).
PairSet from_list(const DemSystem& dem, double extra_m) {
  const auto& p = dem.particles();
  const auto& l = dem.neighbor_list();
  PairSet out;
  for (std::size_t i = 0; i < l.n_owned(); ++i) {
    for (std::uint32_t k = l.offsets()[i]; k < l.offsets()[i + 1]; ++k) {
      const std::size_t j = l.neighbors()[k];
      double r2 = 0.0;
      for (int a = 0; a < 3; ++a) r2 += std::pow(p.position_m()[a][i] - p.position_m()[a][j], 2);
      const double rc = p.radius_m()[i] + p.radius_m()[j] + extra_m;
      if (r2 < rc * rc) {
        const auto key = std::minmax(p.id()[i], p.id()[j]);
        EXPECT_EQ(out.count(key), 0u) << "pair listed twice";
        out.insert(key);
      }
    }
  }
  return out;
}

TEST(NeighborList, EqualsBruteForceAtBuild) {
  for (bool periodic : {false, true}) {
    DemSystem dem = random_particles(periodic, 600, 3);
    dem.initialize();
    const double skin = dem.params().skin_m;
    const PairSet expected = brute_force(dem, skin);
    EXPECT_GT(expected.size(), 100u);
    EXPECT_EQ(from_list(dem, skin), expected) << (periodic ? "periodic" : "open");
  }
}

TEST(NeighborList, StillHoldsEveryContactBetweenRebuilds) {
  DemSystem dem = random_particles(true, 600, 5);
  for (int n = 0; n < 300; ++n) {
    dem.step();
    // Contacts (extra = 0) found through the list equal the brute-force contacts at every step.
    ASSERT_EQ(from_list(dem, 0.0), brute_force(dem, 0.0)) << "step " << n;
  }
  EXPECT_GT(dem.stats().list_builds, 2u);
}

}  // namespace
}  // namespace hs::unresolved
