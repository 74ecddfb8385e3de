// SPDX-License-Identifier: MIT
// The CFD-DEM coupling on z-slabs (issue #28 step 4) against one rank holding the whole grid and every particle: a
// periodic tube of plasma held at a flow rate with RBC spheres at Ht 0.2, two-way coupled (void fraction, implicit
// drag, pressure and viscous forces), 30 coupled steps, the exchange smoothed or not. Run at np 1, 2 and 4
// (oversubscribed).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <vector>

#include "closures/register_builtin.hpp"
#include "common/geometry/tube.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "support/gathered_particles.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/insertion.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

// The tube of the FVM's slab test: 10 cells of 3 um across the box, 20 planes (5 a block at np 4: 15 um, more than
// the DEM's cut-off of a diameter and a skin).
constexpr double kBox = 30e-6;
constexpr double kLength = 60e-6;
constexpr double kDx = 3e-6;
constexpr double kTubeRadius = 12e-6;
constexpr double kMeanVelocity = 2e-3;   // m/s
constexpr double kDtCfd = 1e-5;          // s: Courant 0.01, viscous number nu dt / dx^2 = 1.3
constexpr int kSteps = 30;

const hs::common::Tube& tube() {
  static const hs::common::Tube t({.start_m = {0, 0, 0}, .end_m = {0, 0, kLength}, .radius_m = kTubeRadius});
  return t;
}

FvmGridSpec spec() {
  const double r = 0.5 * kBox;
  FvmGridSpec s{.box_m = {{-r, -r, 0.0}, {r, r, kLength}}, .dx_m = kDx, .sides = {}};
  s.sides[4].type = SideType::periodic;
  s.sides[5].type = SideType::periodic;
  return s;
}

Domain domain() { return {.box = spec().box_m, .periodic = {false, false, true}}; }

int n_coupling() { return static_cast<int>(std::ceil(kDtCfd / (0.1 * rayleigh_time_s(default_particle_params())))); }

/// One run: the whole problem here (slabs null) or this rank's slab of it.
struct CoupledTube {
  CoupledTube(const FvmGrid& grid, DemSlabs* slabs, MPI_Comm comm, double smoothing_length_m, bool footprint,
              bool self_induced)
      : fluid(grid, {.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6},
              {.dt_s = kDtCfd, .pressure = {.tolerance = 1e-12, .rel_tol = 0.0, .max_iterations = 1000},
               .momentum_tolerance = 1e-12},
              {.mode = FlowDrive::Mode::flow_rate, .axis = 2,
               .flow_rate_m3_s = std::numbers::pi * kTubeRadius * kTubeRadius * kMeanVelocity},
              comm),
        dem({.params = default_particle_params(), .domain = domain(), .time_step_s = kDtCfd / n_coupling()}, &tube(),
            slabs) {
    const InsertionResult placed = insert_at_volume_fraction(
        tube(), domain(), {.volume_fraction = 0.2, .radius_m = default_particle_params().radius_m(), .seed = 3});
    for (std::size_t k = 0; k < placed.positions_m.size(); ++k) {
      const Vec3& x = placed.positions_m[k];
      if (slabs == nullptr || (x.z >= slabs->lo_m() && x.z < slabs->hi_m())) {
        (void)dem.add_particle(x, {}, static_cast<std::int64_t>(k));
      }
    }
    CouplingClosures closures;
    closures.drag = hs::closures::make_drag_closure({.model = "stokes", .file = {}});
    coupling = std::make_unique<CfdDemCoupling>(
        fluid, dem,
        CouplingSettings{.n_coupling = n_coupling(), .void_fraction_rate = false, .axis = 2, .axis_point_m = {},
                         .tube_radius_m = kTubeRadius, .self_induced_correction = self_induced,
                         .smoothing_length_m = smoothing_length_m, .buoyancy_over_footprint = footprint},
        std::move(closures));
    coupling->set_mean_velocity_m_s(kMeanVelocity);
  }
  FvmSolver fluid;
  DemSystem dem;
  std::unique_ptr<CfdDemCoupling> coupling;
};

/// The largest |block - whole| over this block's face nodes, over the whole grid's largest value; max over the ranks.
double largest_velocity_difference(const FvmSolver& block, const FvmSolver& whole) {
  const int first = block.grid().first_plane();
  const auto& n = block.grid().cells();
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double scale = 0.0;
    for (const double v : whole.face_velocity(c).data()) scale = std::max(scale, std::abs(v));
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          worst = std::max(worst, std::abs(block.face_velocity(c)(i, j, k) - whole.face_velocity(c)(i, j, first + k)) / scale);
        }
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return worst;
}

void expect_one_rank(double smoothing_length_m, bool footprint,
              bool self_induced) {
  int size = 0;
  int rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const FvmGridSpec s = spec();
  const FvmGrid whole_grid(tube(), s);
  const hs::common::CartesianDecomposition decomposition(
      {.global_nodes = whole_grid.cells(), .periodic = {false, false, true}, .ranks_per_axis = {1, 1, 0}, .ghost = 2},
      MPI_COMM_WORLD);
  const FvmGrid block_grid(tube(), s, &decomposition);
  DemSlabs slabs(decomposition, domain(), kDx);

  CoupledTube alone(whole_grid, nullptr, MPI_COMM_SELF, smoothing_length_m, footprint, self_induced);
  CoupledTube distributed(block_grid, &slabs, MPI_COMM_WORLD, smoothing_length_m, footprint, self_induced);
  for (int step = 0; step < kSteps; ++step) {
    alone.coupling->step();
    distributed.coupling->step();
  }
  const auto a = hs::test::gathered_particles(alone.dem.particles(), MPI_COMM_SELF);
  const auto b = hs::test::gathered_particles(distributed.dem.particles(), MPI_COMM_WORLD);
  ASSERT_EQ(a.size(), b.size()) << "particles lost or duplicated";
  const double d = default_particle_params().diameter_m;
  double worst_x = 0.0;
  double worst_v = 0.0;
  double largest_v = 0.0;
  for (const auto& [id, xv] : a) {
    const auto it = b.find(id);
    ASSERT_NE(it, b.end()) << "particle " << id << " missing";
    Vec3 dx = it->second[0] - xv[0];
    dx.z -= kLength * std::round(dx.z / kLength);
    worst_x = std::max(worst_x, norm(dx) / d);
    worst_v = std::max(worst_v, norm(it->second[1] - xv[1]));
    largest_v = std::max(largest_v, norm(xv[1]));
  }
  worst_v /= largest_v;
  const double worst_u = largest_velocity_difference(distributed.fluid, alone.fluid);
  const ExchangeStats& ea = alone.coupling->exchange();
  const ExchangeStats& eb = distributed.coupling->exchange();
  const double impulse = norm(eb.drag_impulse_particles_N_s - ea.drag_impulse_particles_N_s) / norm(ea.drag_impulse_particles_N_s);
  const double pending = norm(eb.pending_N_s - ea.pending_N_s) / norm(ea.drag_impulse_particles_N_s);
  if (rank == 0) {
    std::printf("coupling (smoothing %.3g m, buoyancy %s%s) on %d slab(s), %zu particles, %d steps: max |x - x_alone| = %.2e d, |v - v_alone| = %.2e "
                "of max |v|, fluid %.2e of max |u|, drag impulse %.2e, pending %.2e of the impulse\n",
                smoothing_length_m, footprint ? "footprint" : "centre",
                self_induced ? ", self-induced correction" : "", size, a.size(), kSteps, worst_x, worst_v, worst_u, impulse, pending);
  }
  EXPECT_GT(a.size(), 20u);
  EXPECT_GT(largest_v, 0.5 * kMeanVelocity) << "the particles did not move: the test would see nothing";
  if (size == 1 && !footprint) {
    // One slab takes every distributed path (the periodic seam through MPI, the fluid sampled by the block holding the
    // centre and sent to the owner, which adds it to zeros): the same operations in the same order.
    EXPECT_EQ(worst_x, 0.0);
    EXPECT_EQ(worst_v, 0.0);
    EXPECT_EQ(worst_u, 0.0);
  } else {
    // The footprint sum of a sphere across the periodic seam is added in two parts (one per copy), on one slab too.
    // Several slabs: the pressure solve's AMG differs per rank (both solve to 1e-12, cond ~1e3: 1e-9 of a field), the
    // smoothing is a CG to 1e-13 where one rank factorises, the DEM sums a particle's contact forces in another order,
    // and the bookkeeping sums over the ranks; 30 steps of overdamped particles in a viscous flow do not amplify
    // round-off: 1e-9 of each quantity.
    EXPECT_LE(worst_x, 1e-9);
    EXPECT_LE(worst_v, 1e-9);
    EXPECT_LE(worst_u, 1e-9);
  }
  EXPECT_LE(impulse, 1e-9);
  EXPECT_LE(pending, 1e-9);
}

TEST(CouplingOnSlabs, FollowsOneRankHoldingTheWholeTube) { expect_one_rank(0.0, false, false); }

// The exchange smoothed over a sphere's diameter (tube-pries' setting): on several slabs a distributed CG (relative
// residual 1e-13) where one rank factorises; on one slab the same factor.
TEST(CouplingOnSlabs, FollowsOneRankWithTheExchangeSmoothed) { expect_one_rank(default_particle_params().diameter_m, false, false); }

// And the generalised buoyancy over the footprint (tube-pries' setting): a sum over the markers' cells, of which a
// neighbour adds those in its cells and sends the part to the owner.
TEST(CouplingOnSlabs, FollowsOneRankWithTheBuoyancyOverTheFootprint) {
  expect_one_rank(default_particle_params().diameter_m, true, false);
}

// tube-pries' coupling: the above and the self-induced velocity correction, whose table each rank measures on the
// whole grid by itself.
TEST(CouplingOnSlabs, FollowsOneRankWithTheSelfInducedCorrection) {
  expect_one_rank(default_particle_params().diameter_m, true, true);
}

}  // namespace
}  // namespace hs::unresolved
