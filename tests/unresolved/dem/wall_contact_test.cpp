// SPDX-License-Identifier: MIT
// Particle-wall contact against the tube's signed distance: Hertz rebound, static load, sliding -> rolling.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Tube;

struct WallSetup {
  ParticleParams params = test::rbcpack_params();
  double tube_radius_m = 200.0 * 3.91e-6;   // >> r: the wall is locally almost flat
  [[nodiscard]] Tube tube() const { return Tube({.start_m = {0, 0, -20e-6}, .end_m = {0, 0, 20e-6}, .radius_m = tube_radius_m}); }
  [[nodiscard]] Domain domain() const {
    const double h = tube_radius_m * 1.01;
    return {.box = {.lo = {-h, -h, -20e-6}, .hi = {h, h, 20e-6}}, .periodic = {false, false, true}};
  }
};

struct WallImpact {
  double contact_time_s;
  double analytic_time_s;
  double restitution;
  double tangential_velocity_m_s;
};

/// A sphere hits the tube wall radially at speed v.
WallImpact wall_impact(double restitution, double v) {
  WallSetup s;
  s.params.particle.restitution = restitution;
  s.params.wall = s.params.particle;
  const double r = s.params.radius_m(), big_r = s.tube_radius_m;
  // Wall contacts use R* = r and m* = m whatever the wall curvature, as LIGGGHTS fix wall/gran does
  // (unresolved-methods.md 4.7); E* from the particle and wall materials.
  const double r_eff = r, m_eff = s.params.mass_kg();
  const double e_eff = HertzContactLaw::combine(s.params.particle, s.params.wall).y_eff_Pa;
  const double delta_max = std::pow(15.0 * m_eff * v * v / (16.0 * e_eff * std::sqrt(r_eff)), 0.4);
  const double t_analytic = 2.94 * delta_max / v;
  s.params.max_impact_velocity_m_s = v;
  const double dt = t_analytic / 1000.0;
  const Tube tube = s.tube();
  DemSystem dem({.params = s.params, .domain = s.domain(), .time_step_s = dt}, &tube);
  dem.add_particle({big_r - r - 0.1 * r, 0, 0}, {v, 0, 0});
  long in_contact = 0;
  bool touched = false;
  for (long n = 0; n < 10000; ++n) {   // contact starts after ~100 steps, lasts ~1100
    dem.step();
    if (dem.stats().wall_contacts > 0) {
      ++in_contact;
      touched = true;
    } else if (touched) {
      break;
    }
  }
  const auto& vel = dem.particles().velocity_m_s();
  return {static_cast<double>(in_contact) * dt, t_analytic, -vel[0][0] / v, vel[1][0]};
}

TEST(WallContact, RadialImpactOnTheTubeWallIsHertzian) {
  const WallImpact elastic = wall_impact(1.0, 5e-3);
  // Same acceptance as the two-sphere case: 2% on the undamped contact time.
  EXPECT_NEAR(elastic.contact_time_s / elastic.analytic_time_s, 1.0, 0.02);
  EXPECT_NEAR(elastic.restitution, 1.0, 1e-3);   // O(dt^2) energy error of velocity Verlet
  const WallImpact damped = wall_impact(0.5, 5e-3);
  std::cout << "measured: wall t_contact / analytic = " << elastic.contact_time_s / elastic.analytic_time_s
            << ", e(set 0.5) = " << damped.restitution << "\n";
  // 1% on the restitution.
  EXPECT_NEAR(damped.restitution / 0.5, 1.0, 0.01);
  // Radial wall: no tangential velocity may appear (normal from the signed-distance gradient).
  EXPECT_NEAR(damped.tangential_velocity_m_s, 0.0, 1e-9 * 5e-3);
}

TEST(WallContact, PressedSlidingSphereSettlesToRollingAndHertzOverlap) {
  WallSetup s;
  s.params.wall = s.params.particle;
  const double r = s.params.radius_m(), big_r = s.tube_radius_m;
  const double e_eff = HertzContactLaw::combine(s.params.particle, s.params.wall).y_eff_Pa;
  const double r_eff = r;   // wall contact: R* = r (LIGGGHTS fix wall/gran)
  const double delta_eq = 0.01 * r;
  const double load = 4.0 / 3.0 * e_eff * std::sqrt(r_eff) * std::pow(delta_eq, 1.5);
  const double v0 = 1e-3;
  const Tube tube = s.tube();
  DemSystem dem({.params = s.params, .domain = s.domain(), .time_step_s = 2e-7}, &tube);
  dem.add_particle({big_r - r + delta_eq, 0, 0}, {0, 0, v0});
  dem.particles().external_force_N()[0][0] = load;
  for (int n = 0; n < 100000; ++n) dem.step();
  const auto& p = dem.particles();
  const double overlap = p.position_m()[0][0] - (big_r - r);
  // Static Hertz load: the overlap returns to (3 F / (4 E* sqrt(R*)))^(2/3) once the normal ringing is damped.
  EXPECT_NEAR(overlap / delta_eq, 1.0, 1e-4);
  // Angular momentum about the contact point is conserved while sliding turns into rolling:
  // m v0 r_c = m v r_c + I v / r_c  =>  v = v0 / (1 + 0.4 r^2 / r_c^2) (5/7 v0 for a rigid contact).
  const double rc = r - 0.5 * delta_eq;
  const double v_roll = v0 / (1.0 + 0.4 * r * r / (rc * rc));
  // 0.5%: the remaining tangential-spring ringing after 100k steps (20 ms, ~40 periods) is smaller than this.
  EXPECT_NEAR(p.velocity_m_s()[2][0] / v_roll, 1.0, 5e-3);
  // Rolling without slip at the contact point: v_z = w_y r_c.
  EXPECT_NEAR(p.angular_velocity_rad_s()[1][0] * rc / p.velocity_m_s()[2][0], 1.0, 5e-3);
}

TEST(WallContact, ParticleOutsideTheGeometryIsAConfigError) {
  WallSetup s;
  const Tube tube = s.tube();
  DemSystem dem({.params = s.params, .domain = s.domain(), .time_step_s = 1e-7}, &tube);
  dem.add_particle({s.tube_radius_m * 1.001, 0, 0});
  EXPECT_THROW(dem.initialize(), hs::common::ConfigError);
}

}  // namespace
}  // namespace hs::unresolved
