// SPDX-License-Identifier: MIT
// Plasma in a periodic straight tube against Hagen-Poiseuille: the acceptance criterion
// (flow rate within 2% with 10 cells across the diameter) and its convergence with resolution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace {

using hs::common::Vec3;
using hs::unresolved::FlowDrive;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;
using hs::unresolved::SideCondition;
using hs::unresolved::SideType;

// Plasma (rbc_blood_properties.csv): rho = 1025 kg/m^3, nu = 1.2e-6 m^2/s; a 20 um tube.
constexpr double kRho = 1025.0;
constexpr double kNu = 1.2e-6;
constexpr double kRadius = 10e-6;
constexpr double kGradient = -2e5;   // Pa/m: centreline velocity G R^2 / (4 mu) = 4.1 mm/s

double poiseuille_flow_rate(double gradient) {
  return std::numbers::pi * std::pow(kRadius, 4) * -gradient / (8.0 * kRho * kNu);
}

struct TubeRun {
  double flow_rate_m3_s;
  double gradient_Pa_m;
};

/// Periodic tube along z, `cells` across the diameter, 4 cells long (the flow is z-invariant), run to
/// steady state: dt = 2e-4 s is 2.4 viscous times R^2/nu, so implicit Euler damps the slowest mode by
/// ~15x per step and 40 steps are converged to round-off.
TubeRun run_tube(int cells, const FlowDrive& drive) {
  const double h = 2.0 * kRadius / cells;
  const double length = 4 * h;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = kRadius});
  FvmGridSpec spec{.box_m = {{-kRadius, -kRadius, 0.0}, {kRadius, kRadius, length}}, .dx_m = h, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  FvmSolver solver(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu},
                   {.dt_s = 2e-4, .correctors = 2, .max_courant = 1.0}, drive);
  for (int s = 0; s < 40; ++s) solver.step();
  return {solver.flow_rate_m3_s(2), solver.drive_pressure_gradient_Pa_m()};
}

TEST(TubePoiseuille, FlowRateWithin2PercentAt10CellsAcross) {
  const FlowDrive drive{.mode = FlowDrive::Mode::pressure_gradient, .axis = 2, .pressure_gradient_Pa_m = kGradient};
  const double exact = poiseuille_flow_rate(kGradient);
  const double err10 = run_tube(10, drive).flow_rate_m3_s / exact - 1.0;
  const double err20 = run_tube(20, drive).flow_rate_m3_s / exact - 1.0;
  std::printf("tube flow rate error vs Poiseuille: 10 cells %+.3f%%, 20 cells %+.3f%%\n", 100 * err10, 100 * err20);
  // Acceptance criterion of issue 7: within 2% at 10 cells across the diameter.
  EXPECT_LT(std::abs(err10), 0.02);
  // Second-order convergence: halving dx must cut the error by ~4; 3 leaves room for the sub-sampled
  // apertures (staircase walls converge erratically and at first order at best).
  EXPECT_LT(std::abs(err20), std::abs(err10) / 3.0);
}

TEST(TubePoiseuille, NodalVelocityIsExactForTheParabola) {
  // The Shortley-Weller wall stencil is exact for quadratics, so the axial velocity at every node matches
  // u = G (r^2 - R^2) / (4 mu) up to the solver tolerances (1e-6 relative), whatever the wall cut.
  const int cells = 10;
  const double h = 2.0 * kRadius / cells;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, 4 * h}, .radius_m = kRadius});
  FvmGridSpec spec{.box_m = {{-kRadius, -kRadius, 0.0}, {kRadius, kRadius, 4 * h}}, .dx_m = h, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  FvmSolver solver(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu}, {.dt_s = 2e-4},
                   {.mode = FlowDrive::Mode::pressure_gradient, .axis = 2, .pressure_gradient_Pa_m = kGradient});
  for (int s = 0; s < 40; ++s) solver.step();
  const double u_max = -kGradient * kRadius * kRadius / (4.0 * kRho * kNu);
  double worst = 0.0;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      if (grid.kind(2, i, j, 1) != hs::unresolved::NodeKind::active) continue;
      const Vec3 p = grid.node_position_m(2, i, j, 1);
      const double exact = u_max * (1.0 - (p.x * p.x + p.y * p.y) / (kRadius * kRadius));
      worst = std::max(worst, std::abs(solver.face_velocity(2)(i, j, 1) - exact) / u_max);
    }
  }
  EXPECT_LT(worst, 1e-4);
  // What the coupling reads at a particle position off the nodes: velocity, shear rate, grad p, div tau.
  const Vec3 x{0.3 * kRadius, 0.2 * kRadius, 1.3 * h};
  const double r2 = x.x * x.x + x.y * x.y;
  // Trilinear interpolation of the parabola errs by at most u'' dx^2 / 8 per direction = u_max / 50 here.
  EXPECT_NEAR(solver.velocity_at(x).z, u_max * (1.0 - r2 / (kRadius * kRadius)), 0.02 * u_max);
  // Shear rate: differences of the interpolant are first order, |error| <= u'' dx / 2 = 10% of the wall
  // shear 2 u_max / R at 10 cells across.
  const auto grad = solver.velocity_gradient_at(x);
  const double wall_shear = 2.0 * u_max / kRadius;
  EXPECT_NEAR(grad[2].x, -2.0 * u_max * x.x / (kRadius * kRadius), 0.1 * wall_shear);
  EXPECT_NEAR(grad[2].y, -2.0 * u_max * x.y / (kRadius * kRadius), 0.1 * wall_shear);
  // Steady Poiseuille: div tau balances grad p (both -G along z); the pressure gradient is the drive.
  EXPECT_NEAR(solver.pressure_gradient_at(x).z, kGradient, 1e-6 * -kGradient);
  EXPECT_NEAR(solver.viscous_force_density_at(x).z / kGradient, 1.0, 0.05);   // second differences, O(dx^2) interp.
}

TEST(TubePoiseuille, PrescribedFlowRateFindsPoiseuilleGradient) {
  const double target = poiseuille_flow_rate(kGradient);
  const FlowDrive drive{.mode = FlowDrive::Mode::flow_rate, .axis = 2, .flow_rate_m3_s = target};
  const TubeRun run = run_tube(10, drive);
  // The controller holds the flow rate to the pressure solver's tolerance.
  EXPECT_NEAR(run.flow_rate_m3_s / target, 1.0, 1e-6);
  // The gradient it needs is Poiseuille's to within the same 2% as the flow rate at fixed gradient.
  EXPECT_NEAR(run.gradient_Pa_m / kGradient, 1.0, 0.02);
}

}  // namespace
