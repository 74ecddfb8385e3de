// SPDX-License-Identifier: MIT
// The coupling applies a learned lift closure with the velocity its C_l was normalised with: the slip u_f - u_p, or
// the fluid velocity u_f relative to the walls (the resolved RBC dataset, docs/coefficients.md "Why C_l uses u(r)"),
// and gives the closure the Re_p of that same velocity.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "closures/register_builtin.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "periodic_tube.hpp"

namespace {

using hs::common::Vec3;
using namespace hs::unresolved;

constexpr double kRho = 1025.0;
constexpr double kNu = 1.2e-6;

/// A lift closure C_l = re_p, so that the force shows both the velocity and the Re_p the coupling used.
std::filesystem::path lift_file(const std::string& reference) {
  const auto p = std::filesystem::temp_directory_path() / ("hs_lift_" + reference + ".toml");
  std::ofstream(p) << "name = \"cl_test\"\nkind = \"lift\"\noutput = \"C_l\"\nexpression = \"re_p\"\n"
                   << "reference_velocity = \"" << reference << "\"\n[variables]\nre_p = \"Re_p\"\n[validity]\nre_p = [0, 1]\n";
  return p;
}

struct LiftCheck {
  double radial_force_N;     // the particle's external force along the radial unit vector
  double expected_N;         // (pi/8) rho d^2 C_l |u|^2 with C_l = d |u| / nu, u the reference velocity
};

/// One sphere at r = 0.5 R in a developing tube flow, moving along the axis at half the local fluid velocity so
/// that slip and flow velocity differ by a factor 2; one-way coupling, pressure and viscous forces off: the only
/// external force is the lift.
LiftCheck lift_on_sphere(const std::string& reference) {
  const double diameter = 30e-6, r = 0.5 * diameter, length = 2.0 * diameter;
  const hs::common::Tube tube = test::tube_along_z(diameter, length);
  const FvmGrid grid = test::periodic_tube_grid(tube, diameter, length);
  const double dt = 1e-5;
  FvmSolver fluid = test::tube_plasma(grid, kRho, kNu, dt, 1e-13);
  DemSystem dem({.params = default_particle_params(), .domain = {.box = {{-r, -r, 0.0}, {r, r, length}}, .periodic = {false, false, true}},
                 .time_step_s = dt / 100},
                &tube);
  dem.add_particle({0.5 * r, 0.0, 0.5 * length}, {0.0, 0.0, 0.0});
  CouplingClosures closures;
  closures.drag = hs::closures::make_drag_closure({.model = "stokes", .file = {}});
  closures.lift = hs::closures::make_lift_closure({.model = "expression", .file = lift_file(reference)});
  CfdDemCoupling coupling(fluid, dem,
                          {.n_coupling = 100, .void_fraction_feedback = false, .two_way = false, .void_fraction_rate = false,
                           .pressure_force = false, .viscous_force = false, .axis = 2, .axis_point_m = {0, 0, 0},
                           .tube_radius_m = r},
                          std::move(closures));
  ParticleStore& p = dem.particles();
  for (int s = 0; s < 5; ++s) {
    coupling.step();
    p.velocity_m_s()[2][0] = 0.5 * p.fluid_velocity_m_s()[2][0];   // hold the sphere at half the fluid's speed
    p.velocity_m_s()[0][0] = p.velocity_m_s()[1][0] = 0.0;
    p.position_m()[0][0] = 0.5 * r;                                 // and at its radius
    p.position_m()[1][0] = 0.0;
  }
  coupling.step();   // evaluates the closures at the state set above, for the next step
  const double d = 2.0 * p.radius_m()[0];
  const Vec3 uf{p.fluid_velocity_m_s()[0][0], p.fluid_velocity_m_s()[1][0], p.fluid_velocity_m_s()[2][0]};
  const Vec3 up{p.velocity_m_s()[0][0], p.velocity_m_s()[1][0], p.velocity_m_s()[2][0]};
  const double u = reference == "flow" ? norm(uf) : norm(uf - up);
  const double expected = std::numbers::pi / 8.0 * kRho * d * d * (d * u / kNu) * u * u;
  return {p.external_force_N()[0][0], expected};
}

TEST(LiftReferenceVelocity, FlowAndSlipClosuresUseTheirOwnVelocityAndReP) {
  const LiftCheck flow = lift_on_sphere("flow");
  const LiftCheck slip = lift_on_sphere("slip");
  ASSERT_GT(flow.expected_N, 0.0);
  // Same formula evaluated twice from the same doubles: only round-off apart.
  EXPECT_NEAR(flow.radial_force_N, flow.expected_N, 1e-9 * flow.expected_N);
  EXPECT_NEAR(slip.radial_force_N, slip.expected_N, 1e-9 * slip.expected_N);
  // The slip is about half the flow velocity here, so the two differ by about 2^3.
  EXPECT_GT(flow.radial_force_N, 4.0 * slip.radial_force_N);
}

}  // namespace
