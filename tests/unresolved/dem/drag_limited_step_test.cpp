// SPDX-License-Identifier: MIT
// The overdamped DEM: the fluid torque integrated exactly (rotation relaxes in I / beta_r = 0.5 us, below any DEM
// step), and the drag-limited step (drag_limited_step.hpp) against the Hertz equilibrium of two spheres pressed
// together by the fluid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/dem/drag_limited_step.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"

namespace hs::unresolved {
namespace {

// Plasma, rbc_blood_properties.csv: mu = 1.2 mPa s. Stokes drag 3 pi mu d and rotlet pi mu d^3 of a sphere.
constexpr double plasma_viscosity_Pa_s = 1.2e-3;

ParticleParams soft_rbc_sphere() {
  ParticleParams p = default_particle_params();
  p.particle.youngs_modulus_Pa = 1e3;   // tube-pries' soft artificial modulus
  p.wall.youngs_modulus_Pa = 1e3;
  return p;
}

double stokes_drag(const ParticleParams& p) { return 3.0 * std::numbers::pi * plasma_viscosity_Pa_s * p.diameter_m; }
double stokes_rotlet(const ParticleParams& p) { return std::numbers::pi * plasma_viscosity_Pa_s * std::pow(p.diameter_m, 3); }

TEST(FluidTorque, RotationRelaxesExactlyAtThreeRelaxationTimesPerStep) {
  ParticleParams params = soft_rbc_sphere();
  const double beta_r = stokes_rotlet(params);
  const double inertia = 0.4 * params.mass_kg() * params.radius_m() * params.radius_m();
  const double tau_r = inertia / beta_r;
  EXPECT_NEAR(tau_r, 0.47e-6, 0.05e-6);   // the 0.5 us of the note
  // dt = 3 tau_r: an explicit torque would multiply the slip by 1 - 3 = -2 per step and diverge.
  const double dt = 3.0 * tau_r;
  params.particle.youngs_modulus_Pa = 1.0;   // no contact here: a soft modulus lets the inertial check admit dt
  DemSystem dem({.params = params, .domain = test::cube(1e-3, true), .time_step_s = dt}, nullptr);
  dem.add_particle({0, 0, 0});
  auto& p = dem.particles();
  p.drag_coefficient_N_s_m()[0] = stokes_drag(params);
  p.rotational_drag_N_m_s()[0] = beta_r;
  const double omega_f = 50.0;   // half the vorticity of a 100 1/s shear
  p.fluid_angular_velocity_rad_s()[1][0] = omega_f;
  for (int n = 1; n <= 10; ++n) {
    dem.step();
    // Exact for a constant Omega_f: round-off of ~50 rad/s values.
    EXPECT_NEAR(p.angular_velocity_rad_s()[1][0], omega_f * -std::expm1(-n * dt / tau_r), 1e-12) << "step " << n;
    EXPECT_EQ(p.angular_velocity_rad_s()[0][0], 0.0);
  }
}

/// Two spheres on the x axis, the fluid pushing them together at +-u: at rest, each presses on the other with its
/// drag beta u, so the overlap is Hertz's under F = beta u.
struct PressedPair {
  ParticleParams params = soft_rbc_sphere();
  double beta = stokes_drag(params);
  double u = 2e-4;   // m/s: a shear of ~40 1/s across one diameter

  void set_fluid(DemSystem& dem) const {
    auto& p = dem.particles();
    for (std::size_t i = 0; i < 2; ++i) {
      p.drag_coefficient_N_s_m()[i] = beta;
      p.rotational_drag_N_m_s()[i] = stokes_rotlet(params);
      p.fluid_velocity_m_s()[0][i] = p.position_m()[0][i] < 0.0 ? u : -u;
    }
  }
  [[nodiscard]] double hertz_overlap() const {
    const PairConstants k = HertzContactLaw::combine(params.particle, params.particle);
    const double r_eff = 0.5 * params.radius_m();
    return std::pow(0.75 * beta * u / (k.y_eff_Pa * std::sqrt(r_eff)), 2.0 / 3.0);
  }
};

TEST(DragLimitedStep, TwoPressedSpheresSettleOnTheHertzOverlapAtTheDragLimitedStep) {
  PressedPair c;
  const double inertial_dt = 0.1 * std::min(rayleigh_time_s(c.params), hertz_time_s(c.params, c.params.max_impact_velocity_m_s));
  DemSystem dem({.params = c.params, .domain = test::cube(1e-4, false), .time_step_s = inertial_dt}, nullptr);
  const double r = c.params.radius_m();
  dem.add_particle({-r - 0.05e-6, 0, 0});   // 0.1 um apart: the closing drift counts before they touch
  dem.add_particle({r + 0.05e-6, 0, 0});
  c.set_fluid(dem);
  const DragLimitedStep first = dem.drag_limited_step();
  ASSERT_TRUE(first.applies) << first.reason;
  // The bound anticipates the coming contact: its rate at Hertz's overlap under beta u, over two mobilities.
  const double delta = c.hertz_overlap();
  EXPECT_GT(first.rate_bound_1_s, 0.0);
  const double dt = first.time_step_s;
  EXPECT_GT(dt, 10.0 * inertial_dt);   // the point of it
  dem.set_time_step_s(dt);
  double delta_now = 0.0;
  for (int n = 0; n < 400; ++n) {
    if (n % 10 == 0) dem.set_time_step_s(std::min(dt, dem.drag_limited_step().time_step_s));
    dem.step();
    auto& p = dem.particles();
    const std::size_t left = p.position_m()[0][0] < p.position_m()[0][1] ? 0 : 1;
    delta_now = 2.0 * r - (p.position_m()[0][1 - left] - p.position_m()[0][left]);
    ASSERT_LT(delta_now, 1.5 * delta) << "step " << n;   // monotone approach: never far past the equilibrium
    c.set_fluid(dem);
  }
  // Steady: the contact force equals the drag beta u, so the overlap is Hertz's. The dashpot and the tangential
  // spring are idle at rest; what is left is the relaxation's remainder (1 - dt lambda)^400, below 1e-9.
  EXPECT_NEAR(delta_now, delta, 1e-6 * delta);
  EXPECT_NEAR(dem.particles().velocity_m_s()[0][0], 0.0, 1e-9 * c.u);
}

TEST(DragLimitedStep, DoesNotApplyWithoutRotationalDragOrWhenUnderdamped) {
  PressedPair c;
  const double inertial_dt = 0.1 * rayleigh_time_s(c.params);
  DemSystem dem({.params = c.params, .domain = test::cube(1e-4, false), .time_step_s = inertial_dt}, nullptr);
  const double r = c.params.radius_m();
  dem.add_particle({-r, 0, 0});
  dem.add_particle({r - 0.1e-6, 0, 0});   // touching
  c.set_fluid(dem);
  auto& p = dem.particles();
  p.rotational_drag_N_m_s()[1] = 0.0;   // free rotation: the tangential spring would oscillate undamped
  EXPECT_FALSE(dem.drag_limited_step().applies);
  c.set_fluid(dem);
  // A drag so weak that the contact oscillates (damping ratio < 1): the inertial step stays.
  for (std::size_t i = 0; i < 2; ++i) p.drag_coefficient_N_s_m()[i] = 1e-3 * c.beta;
  const DragLimitedStep s = dem.drag_limited_step();
  EXPECT_FALSE(s.applies);
  EXPECT_GT(s.rate_bound_1_s * s.inertial_time_s, drag_limited_max_rate_times_tau);
}

}  // namespace
}  // namespace hs::unresolved
