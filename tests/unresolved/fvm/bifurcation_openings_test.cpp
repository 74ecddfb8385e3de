// SPDX-License-Identifier: MIT
// Plasma through a Y bifurcation (common/geometry/bifurcation) whose two daughters leave through the same box face,
// each through its own outlet (#21 acceptance): inlet flow = sum of the outlets within 0.1%, a symmetric bifurcation
// splits 50/50 within 0.5%, and an asymmetric one (narrower daughter, higher outlet pressure, a prescribed flow
// fraction) splits the right way.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/geometry/bifurcation.hpp"
#include "common/geometry/opening_condition.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace {

using hs::common::Opening;
using hs::common::OpeningCondition;
using hs::common::OpeningKind;
using hs::common::Vec3;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;

// Plasma (rbc_blood_properties.csv). Parent: radius 10 um, 10 cells across its diameter (the acceptance's
// resolution), from the inlet at x = -40 um to the junction at the origin; daughters at +-30 deg (opening angle
// 60 deg) to the outlet face x = +40 um, where their axes are 46 um apart. Box 80 x 68 x 20 um = 13600 cells of 2 um.
constexpr double kRho = 1025.0;
constexpr double kNu = 1.2e-6;
constexpr double kParentRadius = 10e-6;
constexpr double kHalfLength = 40e-6;   // inlet at -kHalfLength, outlets at +kHalfLength
constexpr double kHalfAngleDeg = 30.0;
constexpr double kHalfWidth = 34e-6;    // box y extent: daughter axis at 23.1 um + its ellipse 9.24 um + margin
constexpr double kDx = 2e-6;
constexpr double kFlow = std::numbers::pi * kParentRadius * kParentRadius * 1e-3;   // mean 1 mm/s in the parent

struct Daughter {
  double radius_m = 8e-6;
  double pressure_Pa = 0.0;
  double flow_fraction = 0.0;   // > 0: a flow-fraction outlet instead of a pressure outlet
};

struct Split {
  double inlet_m3_s;                 // into the domain
  std::array<double, 2> outlet_m3_s; // out of it
  std::array<double, 3> upper_angle_deg;   // from +x, of the velocity on the upper daughter's axis 0.5, 3 and 10 cells
                                           // before the outlet face (the axis is at 30 deg)
  double ghost_ratio;                      // u_y a quarter cell before the upper outlet's centre / u_y half a cell
                                           // before it (the nodes' row)
};

/// Runs the bifurcation to its quasi-steady Stokes flow (Re = 0.017) and returns the opening fluxes.
/// dt = 2e-4 s is 2.4 viscous times R^2/nu of the parent, 3.8 of the daughters: the split settles within 10 implicit
/// steps (measured: it moves by < 1e-7 between steps 10 and 60); 30 leave a margin. The viscous number
/// nu dt / dx^2 = 60 needs more than two PISO correctors (measured on the symmetric case: with two, an antisymmetric
/// mode grows, the shares swing 0.497 / 0.503 from step to step and the Courant limit stops the run at step 24; three
/// settle it, 60 steps at 0.5 +- 2e-9; four, as in the open tube, are used). Two correctors would need dt <= 5e-5 s
/// (viscous number 15: converging, 0.49998 after 30 steps); at 1e-4 s (30) the mode still grows slowly (0.4982
/// after 60 steps).
Split run(const std::array<Daughter, 2>& d) {
  const double angle = kHalfAngleDeg * std::numbers::pi / 180.0;
  const hs::common::Bifurcation shape({.junction_m = {0, 0, 0},
                                       .parent_radius_m = kParentRadius,
                                       .parent_length_m = kHalfLength,
                                       .daughter_radius_m = {d[0].radius_m, d[1].radius_m},
                                       .daughter_length_m = {2.0 * kHalfLength, 2.0 * kHalfLength},
                                       .daughter_angle_deg = {kHalfAngleDeg, -kHalfAngleDeg}});
  FvmGridSpec spec{.box_m = {{-kHalfLength, -kHalfWidth, -kParentRadius}, {kHalfLength, kHalfWidth, kParentRadius}},
                   .dx_m = kDx, .sides = {}};
  const Opening in{.name = "in", .kind = OpeningKind::inlet, .centre_m = {-kHalfLength, 0, 0}, .normal = {-1, 0, 0},
                   .radius_m = kParentRadius};
  spec.openings.push_back(hs::common::flow_rate_inlet(in, kFlow));
  for (int i = 0; i < 2; ++i) {
    // The daughter's axis meets the face x = kHalfLength at y = +-L tan(angle); the plane cuts the tube in an ellipse
    // of half-axes r / cos(angle) (along y) and r (along z), so the largest disc in it is the tube's radius r.
    const Daughter& di = d[static_cast<std::size_t>(i)];
    const Opening out{.name = i == 0 ? "upper" : "lower", .kind = OpeningKind::outlet,
                      .centre_m = {kHalfLength, (i == 0 ? 1.0 : -1.0) * kHalfLength * std::tan(angle), 0},
                      .normal = {1, 0, 0}, .radius_m = di.radius_m};
    spec.openings.push_back(di.flow_fraction > 0.0 ? hs::common::flow_fraction_outlet(out, di.flow_fraction)
                                                   : hs::common::pressure_outlet(out, di.pressure_Pa));
  }
  const FvmGrid grid(shape, spec);
  FvmSolver solver(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu},
                   {.dt_s = 2e-4, .correctors = 4}, {});
  for (int s = 0; s < 30; ++s) solver.step();
  std::array<double, 3> angle_deg{};
  const std::array<double, 3> cells_before{0.5, 3.0, 10.0};
  for (std::size_t q = 0; q < 3; ++q) {
    const double x = kHalfLength - cells_before[q] * kDx;
    const Vec3 u = solver.velocity_at({x, x * std::tan(angle), 0});
    angle_deg[q] = std::atan2(u.y, u.x) * 180.0 / std::numbers::pi;
  }
  const double y_c = kHalfLength * std::tan(angle);
  const double ghost_ratio = solver.velocity_at({kHalfLength - 0.25 * kDx, y_c, 0}).y /
                             solver.velocity_at({kHalfLength - 0.5 * kDx, y_c, 0}).y;
  return {-solver.opening_flow_rate_m3_s(0), {solver.opening_flow_rate_m3_s(1), solver.opening_flow_rate_m3_s(2)},
          angle_deg, ghost_ratio};
}

double share(const Split& s, int i) { return s.outlet_m3_s[static_cast<std::size_t>(i)] / s.inlet_m3_s; }

/// Mass: what comes in leaves through the two outlets, to the pressure solve's tolerance (the acceptance's 0.1%).
void expect_conserved(const Split& s) {
  EXPECT_NEAR(s.inlet_m3_s / kFlow, 1.0, 1e-12);   // the inlet's discrete flux is the requested flow rate
  EXPECT_NEAR((s.outlet_m3_s[0] + s.outlet_m3_s[1]) / s.inlet_m3_s, 1.0, 1e-3);
}

TEST(BifurcationOpenings, SymmetricSplitsHalfAndHalf) {
  const Split s = run({Daughter{}, Daughter{}});
  std::printf("symmetric bifurcation: (out0 + out1) / in - 1 = %.2e, shares %.6f / %.6f; flow angle on the upper "
              "daughter's axis (30 deg) 10, 3 and 0.5 cells before the outlet: %.2f, %.2f, %.2f deg; u_y ghost ratio "
              "%.12f\n",
              (s.outlet_m3_s[0] + s.outlet_m3_s[1]) / s.inlet_m3_s - 1.0, share(s, 0), share(s, 1),
              s.upper_angle_deg[2], s.upper_angle_deg[1], s.upper_angle_deg[0], s.ghost_ratio);
  expect_conserved(s);
  // Acceptance of #21: 50/50 within 0.5% (each share within 0.5% of one half). The grid is mirror-symmetric about
  // y = 0, so only the iterative solves' ordering breaks the symmetry.
  EXPECT_NEAR(share(s, 0) / 0.5, 1.0, 5e-3);
  EXPECT_NEAR(share(s, 1) / 0.5, 1.0, 5e-3);
  // Beyond a pressure outlet the tangential velocity's ghost is zero-gradient (not the wall's reflection, which would
  // halve u_y a quarter cell before the face): what a particle leaving through the outlet sees.
  EXPECT_NEAR(s.ghost_ratio, 1.0, 1e-12);
  // Ten cells before the face the flow follows the daughter's axis (30 deg) within 1 deg (measured 30.45). Closer,
  // the uniform pressure on a face oblique to the branch turns it towards the face normal: 26.4 deg three cells
  // before, 18.6 half a cell before (printed; a limit of outlets on box faces cutting a branch at an angle).
  EXPECT_NEAR(s.upper_angle_deg[2], kHalfAngleDeg, 1.0);
}

TEST(BifurcationOpenings, AsymmetricSplitsFollowRadiusAndPressure) {
  // A narrower lower daughter (6 um against 8 um): Poiseuille's r^4 gives the wider one (8/6)^4 = 3.2 times the
  // flow for equal lengths and pressures, a share of 0.76; the junction and the coarse narrow branch (6 cells
  // across) change the number, not the direction.
  const Split narrow = run({Daughter{}, Daughter{.radius_m = 6e-6}});
  // Equal daughters, the upper outlet 4 Pa above the lower: a daughter's own Poiseuille drop at half the flow is
  // 8 mu L (Q/2) / (pi r^4) = 5.5 Pa over its 46 um, so the Poiseuille network gives the upper one
  // 1/2 - 4 / (4 x 5.5) = 0.32 of the flow; the junction adds resistance to both.
  const Split pressure = run({Daughter{.pressure_Pa = 4.0}, Daughter{}});
  std::printf("narrow lower daughter: shares %.4f / %.4f (Poiseuille r^4 network: 0.760 / 0.240); upper outlet +4 Pa: "
              "shares %.4f / %.4f (network: 0.32 / 0.68)\n",
              share(narrow, 0), share(narrow, 1), share(pressure, 0), share(pressure, 1));
  expect_conserved(narrow);
  expect_conserved(pressure);
  // The direction, with a margin far above the solver's symmetry error (< 1e-5 above): the wider and the
  // lower-pressure branch take more than half.
  EXPECT_GT(share(narrow, 0), 0.6);
  EXPECT_LT(share(pressure, 0), 0.45);
}

TEST(BifurcationOpenings, PrescribedFlowFractionTakesItsShare) {
  // Upper outlet: 30% of the inflow, imposed with the developed profile; the lower pressure outlet takes the rest.
  const Split s = run({Daughter{.flow_fraction = 0.3}, Daughter{}});
  std::printf("flow-fraction outlet 0.3: shares %.6f / %.6f\n", share(s, 0), share(s, 1));
  EXPECT_NEAR(share(s, 0), 0.3, 1e-12);   // imposed on the discrete faces
  expect_conserved(s);
  EXPECT_NEAR(share(s, 1), 0.7, 1e-3);    // the rest, through the pressure outlet, to mass conservation's 0.1%
}

}  // namespace
