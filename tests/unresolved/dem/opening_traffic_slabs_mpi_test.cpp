// SPDX-License-Identifier: MIT
// Cells in and out of an open tube on z-slabs (issue #28) against one rank holding every particle: spheres dragged
// towards a Poiseuille profile along z, injected at the inlet (z = 0, the bottom slab's) and removed at the outlet
// (z = L, the top slab's), with contacts across the slab faces. Run at np 1, 2 and 4 (oversubscribed).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

#include "common/geometry/tube.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "support/gathered_particles.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/insertion.hpp"
#include "unresolved/dem/opening_traffic.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

constexpr double kRadius = 15e-6;
constexpr double kLength = 80e-6;
constexpr int kPlanes = 32;            // 2.5 um: 8 a slab at np 4 (20 um: the injection region and a cut-off fit)
constexpr double kMeanSpeed = 0.2;     // m/s: a cell near the axis crosses the tube in the run
constexpr double kViscosity = 1.2e-3;  // Pa s
constexpr int kDemSteps = 20;          // per exchange (a CFD step's worth)
constexpr int kExchanges = 150;

const hs::common::Tube& tube() {
  static const hs::common::Tube t({.start_m = {0, 0, 0}, .end_m = {0, 0, kLength}, .radius_m = kRadius});
  return t;
}

Domain domain() {
  return {.box = {.lo = {-kRadius, -kRadius, 0.0}, .hi = {kRadius, kRadius, kLength}}, .periodic = {false, false, false}};
}

ParticleParams params() {
  ParticleParams p = default_particle_params();
  p.max_impact_velocity_m_s = 2.0 * kMeanSpeed;
  return p;
}

Vec3 poiseuille(const Vec3& x) {
  const double s = (x.x * x.x + x.y * x.y) / (kRadius * kRadius);
  return {0.0, 0.0, 2.0 * kMeanSpeed * std::max(0.0, 1.0 - s)};
}

OpeningTrafficSpec traffic() {
  const std::vector<hs::common::Opening> openings{
      {.name = "in", .kind = hs::common::OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {0, 0, -1}, .radius_m = kRadius},
      {.name = "out", .kind = hs::common::OpeningKind::outlet, .centre_m = {0, 0, kLength}, .normal = {0, 0, 1},
       .radius_m = kRadius}};
  return {.openings = openings, .discharge_hematocrit = {0.2, 0.0}, .particles = params(), .seed = 5};
}

struct Result {
  std::map<std::int64_t, std::array<Vec3, 2>> particles;
  std::vector<OpeningCounters> counters;
};

/// The open tube: every particle here (slabs null) or this rank's slab of them.
Result run(DemSlabs* slabs) {
  const ParticleParams p = params();
  DemSystem dem({.params = p, .domain = domain(), .time_step_s = 0.05 * rayleigh_time_s(p)}, &tube(), slabs);
  const InsertionResult placed =
      insert_at_volume_fraction(tube(), domain(), {.volume_fraction = 0.2, .radius_m = p.radius_m(), .seed = 7});
  for (std::size_t k = 0; k < placed.positions_m.size(); ++k) {
    const Vec3& x = placed.positions_m[k];
    if (slabs == nullptr || (x.z >= slabs->lo_m() && x.z < slabs->hi_m())) {
      (void)dem.add_particle(x, {}, static_cast<std::int64_t>(k));
    }
  }
  const double d = p.diameter_m;
  dem.set_force_hook([](ParticleStore& ps) {
    auto& u = ps.fluid_velocity_m_s();
    for (std::size_t i = 0; i < ps.n_owned(); ++i) {
      const Vec3 ui = poiseuille({ps.position_m()[0][i], ps.position_m()[1][i], ps.position_m()[2][i]});
      for (int a = 0; a < 3; ++a) u[static_cast<std::size_t>(a)][i] = ui[a];
    }
  });
  OpeningTraffic openings(traffic(), tube(), domain(), slabs);
  const double dt_exchange = kDemSteps * dem.time_step_s();
  const FluidAtOpenings fluid{.flow_rate_m3_s = {std::numbers::pi * kRadius * kRadius * kMeanSpeed, 0.0},
                              .velocity_m_s = poiseuille};
  for (int e = 0; e < kExchanges; ++e) {
    // The drag of every particle present, the new ones included.
    auto& drag = dem.particles().drag_coefficient_N_s_m();
    std::fill(drag.begin(), drag.end(), 3.0 * std::numbers::pi * kViscosity * d);
    for (int s = 0; s < kDemSteps; ++s) dem.step();
    openings.exchange(dem, dt_exchange, fluid);
  }
  return {hs::test::gathered_particles(dem.particles(), slabs != nullptr ? slabs->comm() : MPI_COMM_SELF),
          openings.summed_counters()};
}

TEST(OpeningTrafficOnSlabs, InjectsAndRemovesWhatOneRankDoes) {
  int size = 0;
  int rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const hs::common::CartesianDecomposition decomposition(
      {.global_nodes = {12, 12, kPlanes}, .periodic = {false, false, false}, .ranks_per_axis = {1, 1, 0}, .ghost = 1},
      MPI_COMM_WORLD);
  DemSlabs slabs(decomposition, domain(), kLength / kPlanes);
  const Result alone = run(nullptr);
  const Result distributed = run(&slabs);

  ASSERT_EQ(alone.counters.size(), 2u);
  ASSERT_EQ(distributed.counters.size(), 2u);
  const std::int64_t in = alone.counters[0].cells_in;
  const std::int64_t out = alone.counters[1].cells_out;
  EXPECT_EQ(distributed.counters[0].cells_in, in);
  EXPECT_EQ(distributed.counters[1].cells_out, out);
  EXPECT_EQ(distributed.counters[0].cells_out, alone.counters[0].cells_out);   // backflow at the inlet: none either way
  EXPECT_GT(in, 10) << "too few cells came in: the test would see little";
  EXPECT_GT(out, 10) << "too few cells went out: the test would see little";
  ASSERT_EQ(distributed.particles.size(), alone.particles.size()) << "cells lost or duplicated";
  double worst = 0.0;
  for (const auto& [id, xv] : alone.particles) {
    const auto it = distributed.particles.find(id);
    ASSERT_NE(it, distributed.particles.end()) << "cell " << id << " missing (or numbered otherwise)";
    worst = std::max(worst, norm(it->second[0] - xv[0]) / params().diameter_m);
  }
  if (rank == 0) {
    std::printf("open tube on %d slab(s): %lld in, %lld out, %zu present; max |x - x_alone| = %.2e d\n", size,
                static_cast<long long>(in), static_cast<long long>(out), alone.particles.size(), worst);
  }
  // The same cells with the same ids at the same places; the contact forces of a particle are summed in another
  // order on slabs (round-off, which the overdamped motion does not amplify: the DEM slab test measures 1e-14 d).
  EXPECT_LE(worst, 1e-9);
}

}  // namespace
}  // namespace hs::unresolved
