// SPDX-License-Identifier: MIT
// Momentum exchange of the coupling: in a fully periodic box the fluid gets exactly minus the DEM's drag
// impulse, so fluid + particle momentum is conserved; and a sphere released in uniform flow relaxes to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "closures/register_builtin.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;

class Everywhere final : public hs::common::Shape {
 public:
  [[nodiscard]] double signed_distance(const Vec3&) const override { return -1.0; }
  [[nodiscard]] hs::common::Box3 bounds() const override { return {{0, 0, 0}, {1, 1, 1}}; }
};

CouplingClosures stokes() {
  CouplingClosures c;
  c.drag = hs::closures::make_drag_closure({.model = "stokes", .file = {}});
  return c;
}

struct PeriodicBox {
  static constexpr double side_m = 60e-6;   // 6 cells of 10 um: periodic length > two neighbour cut-offs
  Everywhere all;
  FvmGrid grid;
  FvmSolver fluid;
  DemSystem dem;
  explicit PeriodicBox(double dt_dem, int n_coupling)
      : grid(all, spec()),
        fluid(grid, {.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6},
              {.dt_s = dt_dem * n_coupling, .pressure = {.tolerance = 1e-12, .rel_tol = 0.0},
               .momentum_tolerance = 1e-13},
              {}),
        dem({.params = default_particle_params(),
             .domain = {.box = {{0, 0, 0}, {side_m, side_m, side_m}}, .periodic = {true, true, true}},
             .time_step_s = dt_dem},
            nullptr) {}
  static FvmGridSpec spec() {
    FvmGridSpec s{.box_m = {{0, 0, 0}, {side_m, side_m, side_m}}, .dx_m = 10e-6, .sides = {}};
    for (auto& side : s.sides) side.type = SideType::periodic;
    return s;
  }
};

TEST(MomentumExchange, FluidPlusParticleMomentumIsConservedInAPeriodicBox) {
  const double dt_dem = 0.1 * rayleigh_time_s(default_particle_params());
  PeriodicBox box(dt_dem, 10);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 12; ++i) {   // 12 RBC spheres at random sites 12 um apart, random velocities ~ 1 mm/s
    const Vec3 x{(5 + 12 * (i % 4)) * 1e-6, (8 + 14 * (i / 4)) * 1e-6, 60e-6 * u(rng)};
    box.dem.add_particle(x, {1e-3 * (u(rng) - 0.3), 1e-3 * (u(rng) - 0.5), 2e-3 * u(rng)});
  }
  CfdDemCoupling coupling(box.fluid, box.dem,
                          {.n_coupling = 10, .fluid_drag = FluidDrag::explicit_impulse, .void_fraction_feedback = false,
                           .pressure_force = false, .viscous_force = false},
                          stokes());
  const Vec3 p0 = coupling.fluid_momentum_kg_m_s() + coupling.particle_momentum_kg_m_s();
  double exchanged = 0.0;
  for (int s = 0; s < 20; ++s) {
    coupling.step();
    exchanged += norm(coupling.exchange().drag_impulse_particles_N_s);
    // The fluid's explicit source is minus the particles' drag impulse (same marker weights): round-off.
    const Vec3 gap = coupling.exchange().explicit_to_fluid_N_s + coupling.exchange().drag_impulse_particles_N_s;
    EXPECT_LT(norm(gap), 1e-12 * norm(p0)) << "step " << s;
  }
  const Vec3 p1 = coupling.fluid_momentum_kg_m_s() + coupling.particle_momentum_kg_m_s();
  ASSERT_GT(exchanged, 0.5 * norm(p0));   // the test is meaningful: most of the momentum went to the fluid
  // Round-off of the momentum solves (tolerance 1e-13) and of ~1e3 face sums: 1e-10 of the initial momentum.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p1[a], p0[a], 1e-10 * norm(p0)) << "axis " << a;
  std::printf("explicit exchange: |dP| / |P0| = %.3e\n", norm(p1 - p0) / norm(p0));
}

TEST(MomentumExchange, ImplicitCouplingRelaxesParticleAndFluidToACommonVelocity) {
  const double dt_dem = 0.1 * rayleigh_time_s(default_particle_params());
  PeriodicBox box(dt_dem, 50);
  box.dem.add_particle({30e-6, 30e-6, 30e-6}, {0.0, 0.0, 1e-3});
  CfdDemCoupling coupling(box.fluid, box.dem, {.n_coupling = 50, .pressure_force = false, .viscous_force = false}, stokes());
  const Vec3 p0 = coupling.particle_momentum_kg_m_s();
  double max_pending = 0.0;
  for (int s = 0; s < 200; ++s) {
    coupling.step();
    max_pending = std::max(max_pending, norm(coupling.exchange().pending_N_s));
  }
  // Fluid + particles minus the imbalance still to be given back. Not round-off: with Ksl in the diagonal A the
  // PISO splitting (final u from H(u*) with non-uniform A) leaves the fluid's momentum change off the exchange
  // terms by a transient; measured 1.1% over the relaxation, bounded here by 2%. explicit_impulse mode is the
  // round-off-conservative one (test above).
  const Vec3 p1 = coupling.fluid_momentum_kg_m_s() + coupling.particle_momentum_kg_m_s() - coupling.exchange().pending_N_s;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p1[a], p0[a], 2e-2 * norm(p0)) << "axis " << a;
  std::printf("implicit coupling: |dP| / |P0| = %.3e\n", norm(p1 - p0) / norm(p0));
  // The pending imbalance is the one-step transient Ksl (U^n - U^{n+1}): bounded by a few % of the exchange.
  EXPECT_LT(max_pending, 0.1 * norm(p0));
  std::printf("implicit coupling: max pending imbalance %.3e of the initial momentum\n", max_pending / norm(p0));
  const double v = box.dem.particles().velocity_m_s()[2][0];
  EXPECT_GT(v, 0.0);
  EXPECT_LT(v, 0.2 * 1e-3);   // the sphere gave most of its momentum to the (much heavier) fluid
}

}  // namespace
