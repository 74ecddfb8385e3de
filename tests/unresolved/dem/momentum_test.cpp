// SPDX-License-Identifier: MIT
// Momentum conservation of a dense, agitated periodic pack (pairs across periodic faces, list rebuilds, threads).
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <iostream>
#include <random>

#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

/// A simple-cubic pack of n^3 spheres at spacing 1.0 d, jittered, with fast random velocities and little damping
/// (e = 0.9), so that contacts form and break and the neighbour list is rebuilt during the run.
DemSystem make_pack(int n, std::uint64_t seed) {
  ParticleParams p = test::rbcpack_params();
  p.particle.restitution = 0.9;
  p.max_impact_velocity_m_s = 0.3;
  const double a = 1.0 * p.diameter_m;
  const double half = 0.5 * a * n;
  DemSystem dem({.params = p, .domain = test::cube(half, true), .time_step_s = 2e-7}, nullptr);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < n; ++k) for (int j = 0; j < n; ++j) for (int i = 0; i < n; ++i) {
    const hs::common::Vec3 x{-half + (i + 0.5) * a + 0.02 * a * u(rng), -half + (j + 0.5) * a + 0.02 * a * u(rng),
                             -half + (k + 0.5) * a + 0.02 * a * u(rng)};
    dem.add_particle(x, {0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)});
  }
  return dem;
}

struct Momentum {
  hs::common::Vec3 total;
  double scale;   // sum of m |v| components: the size round-off is relative to
};

Momentum momentum(const ParticleStore& p) {
  Momentum m{};
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    for (int a = 0; a < 3; ++a) {
      m.total[a] += p.mass_kg()[i] * p.velocity_m_s()[a][i];
      m.scale += p.mass_kg()[i] * std::fabs(p.velocity_m_s()[a][i]);
    }
  }
  return m;
}

/// n^3 spheres for `steps` steps; n = 17 (4913 spheres) is above omp_min_particles, so the threaded loops run.
void expect_conserved(int threads, int n_side, int steps) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  DemSystem dem = make_pack(n_side, 42);
  const Momentum m0 = momentum(dem.particles());
  for (int n = 0; n < steps; ++n) dem.step();
  const Momentum m1 = momentum(dem.particles());
  omp_set_num_threads(before);
  EXPECT_GT(dem.stats().pair_contacts, 50u);   // many simultaneous contacts among 512 spheres
  EXPECT_GT(dem.stats().list_builds, 1u);       // the run crossed neighbour-list rebuilds
  // Round-off: 1500 steps x ~1500 pair forces, each exactly antisymmetric; sums of doubles lose ~1e-16 relative
  // per operation, so 1e-12 of the momentum scale is far above round-off and far below any real force error.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m1.total[a], m0.total[a], 1e-12 * m0.scale) << "axis " << a;
  std::cout << "measured: |P - P0| / sum m|v| = "
            << norm(m1.total - m0.total) / m0.scale << " after " << steps << " steps, " << threads << " thread(s)\n";
  // The pack really exchanged momentum (damped contacts took energy out).
  EXPECT_LT(m1.scale, 0.97 * m0.scale);
}

TEST(Momentum, ConservedToRoundOffInAPeriodicBoxOneThread) { expect_conserved(1, 8, 1500); }
TEST(Momentum, ConservedToRoundOffInAPeriodicBoxTwoThreads) { expect_conserved(2, 17, 150); }

TEST(Momentum, ThreadCountDoesNotChangeTheTrajectoryBeyondRoundOff) {
  omp_set_num_threads(1);
  DemSystem a = make_pack(17, 7);   // above omp_min_particles: the threaded paths run
  for (int n = 0; n < 60; ++n) a.step();
  omp_set_num_threads(2);
  DemSystem b = make_pack(17, 7);
  for (int n = 0; n < 60; ++n) b.step();
  std::vector<double> xa(a.particles().n_owned()), xb(xa.size());
  for (std::size_t i = 0; i < xa.size(); ++i) {
    xa[static_cast<std::size_t>(a.particles().id()[i])] = a.particles().position_m()[0][i];
    xb[static_cast<std::size_t>(b.particles().id()[i])] = b.particles().position_m()[0][i];
  }
  // Different summation order only: positions agree to ~1e-12 relative of the particle size after 60 steps.
  for (std::size_t i = 0; i < xa.size(); ++i) EXPECT_NEAR(xa[i], xb[i], 1e-6 * 7.82e-6);
}

}  // namespace
}  // namespace hs::unresolved
