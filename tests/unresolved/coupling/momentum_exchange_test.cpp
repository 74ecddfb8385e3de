// SPDX-License-Identifier: MIT
// Momentum exchange of the coupling: in a fully periodic box the fluid gets exactly minus the DEM's drag
// impulse, so fluid + particle momentum is conserved; and a sphere released in fluid at rest ends at the analytic
// common velocity m_p v0 / (m_p + m_f).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "closures/register_builtin.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "../everywhere_shape.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;

using hs::test::Everywhere;

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

/// Coupling steps of n_coupling DEM steps in 1.7 ms.
int relaxation_steps(int n_coupling) {
  return static_cast<int>(std::ceil(1.7e-3 / (n_coupling * 0.1 * rayleigh_time_s(default_particle_params()))));
}

/// One sphere at v0 along z in the fluid at rest; returns v_p / U - 1 and <u_f> / U - 1 (fluid momentum over fluid mass)
/// after `steps` coupling steps, U the analytic common velocity.
struct Relaxed {
  double particle_error;
  double fluid_error;
  double momentum_error;   // |P1 - P0| / P0, pending imbalance included
};
Relaxed relax_one_sphere(const CouplingSettings& settings, int steps) {
  const double dt_dem = 0.1 * rayleigh_time_s(default_particle_params());
  PeriodicBox box(dt_dem, settings.n_coupling);
  const double v0 = 1e-3;
  box.dem.add_particle({30e-6, 30e-6, 30e-6}, {0.0, 0.0, v0});
  CfdDemCoupling coupling(box.fluid, box.dem, settings, stokes());
  // Momentum m_p v0 shared by the sphere and the fluid of the box (its volume less the sphere's where eps is fed back).
  const ParticleParams p = default_particle_params();
  const double fluid_mass = 1025.0 * (std::pow(PeriodicBox::side_m, 3) - (settings.void_fraction_feedback ? p.volume_m3() : 0.0));
  const double u_common = p.mass_kg() * v0 / (p.mass_kg() + fluid_mass);
  const double p0 = coupling.particle_momentum_kg_m_s()[2];
  for (int s = 0; s < steps; ++s) coupling.step();
  const double p_fluid = coupling.fluid_momentum_kg_m_s()[2];
  const double p1 = p_fluid + coupling.particle_momentum_kg_m_s()[2] - coupling.exchange().pending_N_s[2];
  return {box.dem.particles().velocity_m_s()[2][0] / u_common - 1.0, p_fluid / fluid_mass / u_common - 1.0,
          std::abs(p1 - p0) / p0};
}

// Dilute limit (eps = 1): the sphere and the fluid end at U = m_p v0 / (m_p + rho V_box) exactly. The slowest decay is
// the box's first diffusive mode, rate 4 pi^2 nu / L^2 = 1.3e4 /s (the sphere's own tau_p = 1.6 us is far faster);
// after 1.7 ms it has decayed by e^-22 = 3e-10 from an initial v0 / U = 2e3: 1e-6 of U. Round-off of the momentum
// solves (tolerance 1e-13) is far below. n_coupling = 10: dt_CFD = 1.7 us, inside the explicit mode's stability limit
// rho / Ksl = 11 us.
TEST(MomentumExchange, DiluteExplicitExchangeReachesTheAnalyticCommonVelocity) {
  const Relaxed r = relax_one_sphere({.n_coupling = 10, .fluid_drag = FluidDrag::explicit_impulse,
                                      .void_fraction_feedback = false, .pressure_force = false, .viscous_force = false},
                                     relaxation_steps(10));
  EXPECT_NEAR(r.particle_error, 0.0, 1e-6);
  EXPECT_NEAR(r.fluid_error, 0.0, 1e-6);
  EXPECT_LT(r.momentum_error, 1e-10);   // as the explicit test above
  std::printf("dilute explicit_impulse: v_p / U - 1 = %.2e, <u_f> / U - 1 = %.2e, |dP| / P0 = %.2e\n", r.particle_error,
              r.fluid_error, r.momentum_error);
}

// The same with Ksl in the fluid matrix (the default). It is not exact: the solver's row takes Ksl Us at a face as
// (face mean of Ksl) x (face mean of Us), and Us is 0 in the cells without particles, so at the faces around the sphere's
// cells the fluid is pulled towards half the sphere's velocity even when both move together; the deferred give-back
// then balances that pull, and the sphere settles 1.2% faster than the fluid (with the face mean of the product,
// Ksl-weighted, it reaches U to 5e-9 like the explicit mode: reported, not changed here, because it also changes
// two-way runs with d_p > dx, sphere_in_tube_drag_test). Band: the "few per cent", 2%.
TEST(MomentumExchange, DiluteImplicitExchangeReachesTheCommonVelocityWithinTwoPercent) {
  const Relaxed r = relax_one_sphere({.n_coupling = 10, .fluid_drag = FluidDrag::implicit, .void_fraction_feedback = false,
                                      .pressure_force = false, .viscous_force = false},
                                     relaxation_steps(10));
  EXPECT_NEAR(r.particle_error, 0.0, 0.02);
  EXPECT_NEAR(r.fluid_error, 0.0, 0.02);
  std::printf("dilute implicit: v_p / U - 1 = %.2e, <u_f> / U - 1 = %.2e, |dP| / P0 = %.2e\n", r.particle_error,
              r.fluid_error, r.momentum_error);
}

// Model A with the void-fraction feedback and the sphere's pressure-gradient and viscous forces. (The test this replaces
// had the feedback without those forces: then the fluid's -eps grad p and eps-weighted stress do not integrate to zero
// over the box and 1.1% of the momentum appears, in the explicit mode too, so it was not the PISO splitting.)
// dt_CFD = 8.3 us > tau_p: the implicit mode's regime. Band: the "few per cent", 2%; measured 1.1% for the
// sphere, of which 0.3% is the discrete model A (its forces on the sphere are interpolated at the centre, the fluid's
// are face sums of the marker-quantised eps; the same with the fix above) and the rest the face value above.
TEST(MomentumExchange, ImplicitModelAReachesTheAnalyticCommonVelocity) {
  const Relaxed r = relax_one_sphere({.n_coupling = 50}, 200);
  EXPECT_NEAR(r.particle_error, 0.0, 0.02);
  EXPECT_NEAR(r.fluid_error, 0.0, 0.02);
  EXPECT_LT(r.momentum_error, 0.02);
  std::printf("model A implicit: v_p / U - 1 = %.2e, <u_f> / U - 1 = %.2e, |dP| / P0 = %.2e\n", r.particle_error,
              r.fluid_error, r.momentum_error);
}

// The same two checks with the fields smoothed over 12 um (diffusion_smoothing.hpp; 1.2 cells of this box): the
// smoothing conserves what the particles put on the grid, so the fluid still gets exactly minus the particles' drag
// impulse. Band: the CG's relative residual 1e-13 over 216 cells, summed: 1e-11 of the momentum.
TEST(MomentumExchange, SmoothedExchangeStillConservesMomentum) {
  const double dt_dem = 0.1 * rayleigh_time_s(default_particle_params());
  PeriodicBox box(dt_dem, 10);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 12; ++i) {
    const Vec3 x{(5 + 12 * (i % 4)) * 1e-6, (8 + 14 * (i / 4)) * 1e-6, 60e-6 * u(rng)};
    box.dem.add_particle(x, {1e-3 * (u(rng) - 0.3), 1e-3 * (u(rng) - 0.5), 2e-3 * u(rng)});
  }
  CfdDemCoupling coupling(box.fluid, box.dem,
                          {.n_coupling = 10, .fluid_drag = FluidDrag::explicit_impulse, .void_fraction_feedback = false,
                           .pressure_force = false, .viscous_force = false, .smoothing_length_m = 12e-6},
                          stokes());
  const Vec3 p0 = coupling.fluid_momentum_kg_m_s() + coupling.particle_momentum_kg_m_s();
  for (int s = 0; s < 20; ++s) {
    coupling.step();
    const Vec3 gap = coupling.exchange().explicit_to_fluid_N_s + coupling.exchange().drag_impulse_particles_N_s;
    EXPECT_LT(norm(gap), 1e-11 * norm(p0)) << "step " << s;
  }
  const Vec3 p1 = coupling.fluid_momentum_kg_m_s() + coupling.particle_momentum_kg_m_s();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p1[a], p0[a], 1e-10 * norm(p0)) << "axis " << a;
}

// Model A with smoothing: the same analytic common velocity and the same 2% band as without (the reference is exact;
// the band is the "few per cent"). The smoothed Us (Ksl-weighted) removes most of the face-mean pull the
// unsmoothed test above explains.
TEST(MomentumExchange, SmoothedModelAReachesTheAnalyticCommonVelocity) {
  CouplingSettings settings{.n_coupling = 50};
  settings.smoothing_length_m = 12e-6;
  const Relaxed r = relax_one_sphere(settings, 200);
  EXPECT_NEAR(r.particle_error, 0.0, 0.02);
  EXPECT_NEAR(r.fluid_error, 0.0, 0.02);
  EXPECT_LT(r.momentum_error, 0.02);
  std::printf("model A implicit, smoothed over 12 um: v_p / U - 1 = %.2e, <u_f> / U - 1 = %.2e, |dP| / P0 = %.2e\n",
              r.particle_error, r.fluid_error, r.momentum_error);
}

}  // namespace

namespace {

/// Sum over the spheres of the generalised buoyancy the coupling gave them, and the fluid's own (1 - eps) share of
/// its force density -grad p + div tau at the cell centres, sum_c (1 - eps_c) V_c q_c, after one more coupled step.
std::pair<Vec3, Vec3> buoyancy_and_fluid_share(bool footprint, double smoothing_length_m) {
  const double dt_dem = 0.1 * rayleigh_time_s(default_particle_params());
  PeriodicBox box(dt_dem, 10);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 12; ++i) {   // as above: the spheres' drag stirs the fluid, so grad p and div tau are not zero
    const Vec3 x{(5 + 12 * (i % 4)) * 1e-6, (8 + 14 * (i / 4)) * 1e-6, 60e-6 * u(rng)};
    box.dem.add_particle(x, {1e-3 * (u(rng) - 0.3), 1e-3 * (u(rng) - 0.5), 2e-3 * u(rng)});
  }
  CouplingSettings settings{.n_coupling = 10, .void_fraction_rate = false};
  settings.smoothing_length_m = smoothing_length_m;
  settings.buoyancy_over_footprint = footprint;
  CfdDemCoupling coupling(box.fluid, box.dem, settings, stokes());
  for (int s = 0; s < 5; ++s) coupling.step();
  const ParticleStore& p = box.dem.particles();
  Vec3 spheres{};
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    spheres += Vec3{p.external_force_N()[0][i], p.external_force_N()[1][i], p.external_force_N()[2][i]};
  }
  Vec3 fluid{};
  const auto& n = box.grid.cells();
  const double v = std::pow(box.grid.dx_m(), 3);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const Vec3 x = box.grid.cell_centre_m(i, j, k);
        const Vec3 q = box.fluid.viscous_force_density_at(x) - box.fluid.pressure_gradient_at(x);
        fluid += (1.0 - box.fluid.void_fraction()[box.fluid.void_fraction().index(i, j, k)]) * v * q;
      }
    }
  }
  return {spheres, fluid};
}

}  // namespace

// Model A closes the mixture's momentum only if the spheres receive, in sum, the solid share of the fluid's force
// density that the fluid itself gives up (it carries eps (-grad p + div tau)). Taken over the footprint (the smoothed
// field averaged over the markers' cells: the adjoint of the volume deposit), the sum is exact to the smoothing's
// residual (1e-13 relative per field, summed over 216 cells: 1e-9 of the sum's size). Sampled at the centres it is not
// (the control): each centre value holds the sphere's own reaction, peaked there (docs/cfd-dem.md; in the D = 30 um
// tube this pushed cells and fluid forward, mu_rel 0.985 for rigid spheres, below the Stokes bound 1).
TEST(MomentumExchange, GeneralisedBuoyancyOverTheFootprintIsTheFluidsSolidShare) {
  for (const double l : {0.0, 12e-6}) {
    const auto [spheres, fluid] = buoyancy_and_fluid_share(true, l);
    ASSERT_GT(norm(fluid), 0.0);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(spheres[a], fluid[a], 1e-9 * norm(fluid)) << "l = " << l << ", axis " << a;
    const auto [centre, share] = buoyancy_and_fluid_share(false, l);
    std::printf("l = %.0f um: footprint |sum - share| / |share| = %.2e, centre %.2e\n", l * 1e6,
                norm(spheres - fluid) / norm(fluid), norm(centre - share) / norm(share));
    EXPECT_GT(norm(centre - share), 1e-3 * norm(share)) << "l = " << l;   // the control fails the same band
  }
}
