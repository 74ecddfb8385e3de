// SPDX-License-Identifier: MIT
// Exact (exponential) integration of the linear drag: stability and accuracy at dt = 10 tau_p.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

// RBC-volume sphere in plasma: Stokes drag beta = 3 pi mu d, mu = 1.2 mPa s (rbc_blood_properties.csv).
constexpr double plasma_viscosity_Pa_s = 1.2e-3;

struct DragCase {
  ParticleParams params = default_particle_params();
  double beta = 3.0 * std::numbers::pi * plasma_viscosity_Pa_s * params.diameter_m;
  double tau = params.mass_kg() / beta;   // particle relaxation time (~1.6 us)
};

/// One free particle (no contacts): a soft artificial modulus (1 Pa) lets the DEM time-step check admit
/// dt = 10 tau_p; contacts play no role here.
DemSystem free_particle(DragCase& c, double dt) {
  c.params.particle.youngs_modulus_Pa = 1.0;
  DemSystem dem({.params = c.params, .domain = test::cube(1e-3, true), .time_step_s = dt}, nullptr);
  dem.add_particle({0, 0, 0});
  return dem;
}

TEST(DragIntegration, RelaxationIsExactAndStableAtTenRelaxationTimes) {
  DragCase c;
  EXPECT_NEAR(c.tau, 1.6e-6, 0.2e-6);   // the "~2 us" of the issue, for d = 5.64 um, rho = 1100
  const double dt = 10.0 * c.tau;
  DemSystem dem = free_particle(c, dt);
  const double u_f = 1e-3;
  auto& p = dem.particles();
  p.drag_coefficient_N_s_m()[0] = c.beta;
  p.fluid_velocity_m_s()[0][0] = u_f;
  for (int n = 1; n <= 20; ++n) {
    dem.step();
    const double t = n * dt;
    const double v_exact = u_f * -std::expm1(-t / c.tau);
    // Velocity: exact solution composed of exact half steps; only round-off remains.
    EXPECT_NEAR(p.velocity_m_s()[0][0], v_exact, 1e-14) << "step " << n;
    // Position lags the exact one by at most u_f tau (the exact relaxation lag), never grows.
    const double x_exact = u_f * (t - c.tau * -std::expm1(-t / c.tau));
    EXPECT_LE(std::fabs(p.position_m()[0][0] - x_exact), u_f * c.tau * (1.0 + 1e-9)) << "step " << n;
  }
  // The impulse handed to the fluid equals the particle's momentum gain (no other force acts).
  EXPECT_NEAR(p.drag_impulse_N_s()[0][0], p.mass_kg()[0] * p.velocity_m_s()[0][0], 1e-12 * p.mass_kg()[0] * u_f);
}

TEST(DragIntegration, TerminalVelocityWithAConstantForce) {
  DragCase c;
  const double dt = 10.0 * c.tau;
  DemSystem dem = free_particle(c, dt);
  auto& p = dem.particles();
  const double force = 1e-12, u_f = -2e-4;
  p.drag_coefficient_N_s_m()[0] = c.beta;
  p.fluid_velocity_m_s()[2][0] = u_f;
  p.external_force_N()[2][0] = force;
  p.velocity_m_s()[2][0] = 5e-3;   // starts far from equilibrium
  const double v0 = 5e-3, v_inf = u_f + force / c.beta;
  for (int n = 1; n <= 10; ++n) {
    dem.step();
    const double v_exact = v_inf + (v0 - v_inf) * std::exp(-n * dt / c.tau);
    // Exact for constant F and u_f: round-off of ~1e-3 m/s values.
    EXPECT_NEAR(p.velocity_m_s()[2][0], v_exact, 1e-15) << "step " << n;
  }
}

TEST(DragIntegration, SecondOrderPositionAtSmallSteps) {
  // dt = tau/10 and tau/20: the position error against the exact relaxation shrinks ~4x (velocity Verlet order 2).
  double err[2];
  for (int k = 0; k < 2; ++k) {
    DragCase c;
    const double dt = c.tau / (10.0 * (k + 1));
    DemSystem dem = free_particle(c, dt);
    auto& p = dem.particles();
    p.drag_coefficient_N_s_m()[0] = c.beta;
    p.fluid_velocity_m_s()[1][0] = 1e-3;
    const int steps = 30 * (k + 1);
    for (int n = 0; n < steps; ++n) dem.step();
    const double t = steps * dt;
    err[k] = std::fabs(p.position_m()[1][0] - 1e-3 * (t - c.tau * -std::expm1(-t / c.tau)));
  }
  // Ratio 4 for second order; 3.5-4.5 allows the higher-order terms at dt = tau/10.
  EXPECT_GT(err[0] / err[1], 3.5);
  EXPECT_LT(err[0] / err[1], 4.5);
}

}  // namespace
}  // namespace hs::unresolved
