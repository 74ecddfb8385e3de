// SPDX-License-Identifier: MIT
// The grid's self-mobility in the CFD-DEM tube: the measured table and its use in the tube frame.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "unresolved/coupling/self_mobility.hpp"
#include "unresolved/dem/particle_params.hpp"
#include "periodic_tube.hpp"

namespace {

using namespace hs::unresolved;
using hs::common::Vec3;

constexpr double kRho = 1025.0;   // plasma, rbc_blood_properties.csv
constexpr double kNu = 1.2e-6;

TEST(SelfMobility, TableInAClosedTubeFollowsTheWallAndTheReturnFlow) {
  // D = 100 um, 10 cells across, the RBC sphere (d_p / dx = 0.56), no net flux (as sphere_in_tube_drag_test).
  const double diameter = 100e-6;
  const hs::common::Tube tube = test::tube_along_z(diameter, 2.0 * diameter);
  const FvmGrid grid = test::periodic_tube_grid(tube, diameter, 2.0 * diameter);
  const double d = default_particle_params().diameter_m;
  const SelfMobility m(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu},
                       {.mode = FlowDrive::Mode::flow_rate, .axis = 2, .flow_rate_m3_s = 0.0},
                       {.axis = 2, .axis_point_m = {0, 0, 0}, .radius_m = 0.5 * diameter}, d, 0.1);
  const double beta = 3.0 * std::numbers::pi * kRho * kNu * d;
  const auto& table = m.mobility_m_s_N();
  for (std::size_t k = 0; k < table.size(); ++k) {
    std::printf("rho = %5.2f um: beta M = %.4f axial, %.4f radial, %.4f azimuthal\n", m.station_radii_m()[k] * 1e6,
                beta * table[k][0], beta * table[k][1], beta * table[k][2]);
    for (int c = 0; c < 3; ++c) EXPECT_GT(table[k][c], 0.0) << "station " << k;   // a force drags the fluid its way
  }
  // The no-slip wall holds the fluid back: a sphere touching it (last station) moves less fluid than one on the axis.
  for (int c = 0; c < 3; ++c) EXPECT_LT(table.back()[c], table.front()[c]) << "component " << c;
  // No net flux: an axial force drives a return flow that the transverse ones do not.
  EXPECT_LT(table.front()[0], table.front()[1]);
  // Point particle: below the sphere's own mobility everywhere (beta M < 1), the regime the correction is for.
  for (const Vec3& v : table) EXPECT_LT(beta * std::max({v[0], v[1], v[2]}), 1.0);

  // In the tube frame: at a station on the +y ray (the table was measured on +x), an x force is azimuthal there.
  const double rho = m.station_radii_m()[3];
  const Vec3 u = m.induced_velocity({0.0, rho, 0.3 * diameter}, {2e-12, 0.0, 1e-12});
  EXPECT_NEAR(u[0], 2e-12 * table[3][2], 1e-9 * std::abs(u[0]));
  EXPECT_NEAR(u[1], 0.0, 1e-12 * std::abs(u[0]));
  EXPECT_NEAR(u[2], 1e-12 * table[3][0], 1e-9 * std::abs(u[2]));
}

}  // namespace
