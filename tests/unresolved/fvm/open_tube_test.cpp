// SPDX-License-Identifier: MIT
// Plasma in an open straight tube (velocity inlet at x = 0, pressure outlet at x = L), the first acceptance
// check of #21: the flow rate through every cross-section against the inlet's (within 0.1%) and the profile
// against Hagen-Poiseuille at 10 cells across the diameter (within 2%), for a developed (parabolic) and a
// uniform inlet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace {

using hs::common::Vec3;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;
using hs::unresolved::NodeKind;
using hs::unresolved::SideType;

// Plasma (rbc_blood_properties.csv): rho = 1025 kg/m^3, nu = 1.2e-6 m^2/s; a 20 um tube, 10 diameters long.
constexpr double kRho = 1025.0;
constexpr double kNu = 1.2e-6;
constexpr double kRadius = 10e-6;
constexpr double kLength = 200e-6;
constexpr double kMean = 1e-3;   // m/s, mean velocity of the inlet profile (Re = U D / nu = 0.017)
constexpr int kCells = 10;       // across the diameter

double poiseuille_u(const Vec3& x) {
  const double s = (x.y * x.y + x.z * x.z) / (kRadius * kRadius);
  return 2.0 * kMean * std::max(0.0, 1.0 - s);
}

struct OpenTubeRun {
  std::vector<double> section_flux_m3_s;   // through every x-face plane, inlet (i = 0) to outlet (i = n)
  double profile_error = 0.0;              // max |u - u_Poiseuille(Q)| / u_max over the active nodes of the section
  double flux_vs_nominal = 0.0;            // inlet flux / (pi R^2 U)
  double profile_error_nominal = 0.0;      // the same against the Poiseuille profile of mean U (the inlet's)
};

/// Runs to steady state: dt = 2e-4 s is 2.4 viscous times R^2/nu (implicit Euler damps the slowest radial mode
/// ~15x per step) and Courant 0.2 on the axis; at Re = 0.017 the flow is quasi-steady Stokes flow, so 40 steps
/// converge it as they do the periodic tube (tube_poiseuille_test; here the pressure solve needs 2-4 iterations
/// per step at the end). Four PISO correctors, not the default two: at the viscous number nu dt / dx^2 = 60 two
/// correctors let the known PISO mode grow (docs/cfd-dem.md, "blown up at 60"): here an odd-even oscillation in
/// time mid-tube, x1.2 every two steps, past the Courant limit at step 14. Four correctors settle it (measured; so
/// do dt = 1e-5 s with two, and the projection, which is 8.6% off the profile after 40 steps: slower to converge).
OpenTubeRun run(const std::function<Vec3(const Vec3&)>& inlet, double profile_x_m) {
  const double h = 2.0 * kRadius / kCells;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {kLength, 0, 0}, .radius_m = kRadius});
  FvmGridSpec spec{.box_m = {{0, -kRadius, -kRadius}, {kLength, kRadius, kRadius}}, .dx_m = h, .sides = {}};
  spec.sides[0].type = SideType::velocity_inlet;
  spec.sides[0].inlet_velocity_m_s = inlet;
  spec.sides[1].type = SideType::pressure_outlet;
  const FvmGrid grid(tube, spec);
  FvmSolver solver(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu}, {.dt_s = 2e-4, .correctors = 4}, {});
  for (int s = 0; s < 40; ++s) solver.step();

  // Plasma (eps = 1): the flux of an x-face is aperture x h^2 x u, as the solver's own fluxes (update_fluxes).
  const auto& u = solver.face_velocity(0);
  const auto& ap = grid.apertures(0);
  OpenTubeRun out;
  for (int i = 0; i < grid.node_count(0, 0); ++i) {
    double q = 0.0;
    for (int k = 0; k < grid.node_count(0, 2); ++k) {
      for (int j = 0; j < grid.node_count(0, 1); ++j) q += ap(i, j, k) * h * h * u(i, j, k);
    }
    out.section_flux_m3_s.push_back(q);
  }
  out.flux_vs_nominal = out.section_flux_m3_s.front() / (std::numbers::pi * kRadius * kRadius * kMean);
  // Poiseuille with the flow rate the solver carries (its discrete inlet flux), not the nominal one.
  const double u_max = 2.0 * out.section_flux_m3_s.front() / (std::numbers::pi * kRadius * kRadius);
  const int i = static_cast<int>(std::lround(profile_x_m / h));
  for (int k = 0; k < grid.node_count(0, 2); ++k) {
    for (int j = 0; j < grid.node_count(0, 1); ++j) {
      if (grid.kind(0, i, j, k) != NodeKind::active) continue;
      const Vec3 p = grid.node_position_m(0, i, j, k);
      const double exact = u_max * (1.0 - (p.y * p.y + p.z * p.z) / (kRadius * kRadius));
      out.profile_error = std::max(out.profile_error, std::abs(u(i, j, k) - exact) / u_max);
      out.profile_error_nominal = std::max(out.profile_error_nominal, std::abs(u(i, j, k) - poiseuille_u(p)) / (2.0 * kMean));
    }
  }
  return out;
}

double worst_section_deviation(const OpenTubeRun& r) {
  double worst = 0.0;
  for (const double q : r.section_flux_m3_s) worst = std::max(worst, std::abs(q / r.section_flux_m3_s.front() - 1.0));
  return worst;
}

TEST(OpenTube, DevelopedInletKeepsPoiseuilleAndConservesTheFlowRate) {
  const OpenTubeRun r = run([](const Vec3& x) { return Vec3{poiseuille_u(x), 0, 0}; }, 0.5 * kLength);
  const double dev = worst_section_deviation(r);
  std::printf("open tube, developed inlet: sections vs inlet max %.2e, profile at L/2 vs Poiseuille(Q) %.2e and vs "
              "Poiseuille(U) %.2e of u_max, inlet flux / (pi R^2 U) = %.4f\n",
              dev, r.profile_error, r.profile_error_nominal, r.flux_vs_nominal);
  // Acceptance of #21: every cross-section carries the inlet's flow rate within 0.1% (mass conservation; the
  // pressure solve's 1e-6 tolerance is the real floor).
  EXPECT_LT(dev, 1e-3);
  // Acceptance of #21: the profile within 2% of Poiseuille at 10 cells across. Against the Poiseuille profile of the
  // flow rate the grid carries: the nodes hold the exact parabola (Shortley-Weller is exact for it) and the
  // difference is the cut-face flux error below.
  EXPECT_LT(r.profile_error, 0.02);
  EXPECT_LT(r.profile_error_nominal, 1e-5);   // nodal values: the inlet's parabola (measured 4e-9; solver tolerances 1e-6)
  // The cut-face apertures carry 0.7% more than pi R^2 U for the exact parabola at 10 cells across: the same 2% as
  // the periodic tube's flow-rate criterion (tube_poiseuille_test). A flow-rate inlet must scale its profile by it.
  EXPECT_NEAR(r.flux_vs_nominal, 1.0, 0.02);
}

TEST(OpenTube, UniformInletDevelopsIntoPoiseuille) {
  const OpenTubeRun r = run([](const Vec3& x) { return Vec3{x.y * x.y + x.z * x.z < kRadius * kRadius ? kMean : 0.0, 0, 0}; },
                            0.75 * kLength);
  const double dev = worst_section_deviation(r);
  std::printf("open tube, uniform inlet: sections vs inlet max %.2e, profile at 3L/4 vs Poiseuille(Q) %.2e of u_max, "
              "inlet flux / (pi R^2 U) = %.4f\n", dev, r.profile_error, r.flux_vs_nominal);
  EXPECT_LT(dev, 1e-3);   // as above
  // A uniform U on the inlet's cut faces carries 9% more than pi R^2 U at 10 cells across (the apertures weight the
  // face-centre value as if it vanished at the wall): printed, not asserted; a flow-rate inlet must normalise by it.
  // At Re = 0.017 the entrance length is ~0.6 D (creeping flow): 7.5 D downstream the profile is developed,
  // to the same 2%.
  EXPECT_LT(r.profile_error, 0.02);
}

}  // namespace
