// SPDX-License-Identifier: MIT
// Plasma in an open straight tube whose boundary conditions are named openings (#21 acceptance): a flow-rate inlet
// and a pressure outlet with its own pressure. Every cross-section carries the inlet's flow rate within 0.1%, the
// developed profile is within 2% of Hagen-Poiseuille at 10 cells across the diameter, and the pressure holds the
// outlet's value with the Poiseuille gradient.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "common/geometry/opening_condition.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace {

using hs::common::Opening;
using hs::common::OpeningKind;
using hs::common::Vec3;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;
using hs::unresolved::NodeKind;

// Plasma (rbc_blood_properties.csv): rho = 1025 kg/m^3, nu = 1.2e-6 m^2/s; a 20 um tube, 10 diameters long, as in
// open_tube_test.cpp (the per-side version of this test).
constexpr double kRho = 1025.0;
constexpr double kNu = 1.2e-6;
constexpr double kRadius = 10e-6;
constexpr double kLength = 200e-6;
constexpr double kFlow = std::numbers::pi * kRadius * kRadius * 1e-3;   // m^3/s: mean velocity 1 mm/s, Re = 0.017
constexpr double kOutletPressure = 40.0;                                 // Pa, any gauge: the outlet's own value
constexpr int kCells = 10;                                               // across the diameter

TEST(OpenTubeOpenings, FlowRateInletAndPressureOutletGivePoiseuille) {
  const double h = 2.0 * kRadius / kCells;
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {kLength, 0, 0}, .radius_m = kRadius});
  FvmGridSpec spec{.box_m = {{0, -kRadius, -kRadius}, {kLength, kRadius, kRadius}}, .dx_m = h, .sides = {}};
  const Opening in{.name = "in", .kind = OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {-1, 0, 0},
                   .radius_m = kRadius};
  const Opening out{.name = "out", .kind = OpeningKind::outlet, .centre_m = {kLength, 0, 0}, .normal = {1, 0, 0},
                    .radius_m = kRadius};
  spec.openings = {hs::common::flow_rate_inlet(in, kFlow), hs::common::pressure_outlet(out, kOutletPressure)};
  const FvmGrid grid(tube, spec);
  // dt, steps and correctors as open_tube_test.cpp: dt = 2e-4 s is 2.4 viscous times R^2/nu, 40 steps reach the
  // quasi-steady Stokes flow; the viscous number nu dt / dx^2 = 60 needs four PISO correctors (two blow up there).
  FvmSolver solver(grid, {.density_kg_m3 = kRho, .kinematic_viscosity_m2_s = kNu}, {.dt_s = 2e-4, .correctors = 4}, {});
  for (int s = 0; s < 40; ++s) solver.step();

  // The inlet imposes the flow rate on the discrete faces exactly (round-off), not pi R^2 U with the +0.7% of the
  // cut faces that open_tube_test.cpp found.
  const double q_in = -solver.opening_flow_rate_m3_s(0);
  EXPECT_NEAR(q_in / kFlow, 1.0, 1e-12);
  // Acceptance of #21: every cross-section (each x-face plane, inlet to outlet) within 0.1% of the inlet's flow rate.
  const auto& u = solver.face_velocity(0);
  const auto& ap = grid.apertures(0);
  double worst = 0.0;
  for (int i = 0; i < grid.node_count(0, 0); ++i) {
    double q = 0.0;
    for (int k = 0; k < kCells; ++k) {
      for (int j = 0; j < kCells; ++j) q += ap(i, j, k) * h * h * u(i, j, k);
    }
    worst = std::max(worst, std::abs(q / kFlow - 1.0));
  }
  const double q_out = solver.opening_flow_rate_m3_s(1);
  // Acceptance of #21: the developed profile mid-tube within 2% of u_max of the Poiseuille profile of kFlow. The nodes
  // hold a parabola (Shortley-Weller is exact for it) scaled by the inlet's discrete-flux normalisation, so the
  // error is that normalisation (~0.7% at 10 cells across).
  const double u_max = 2.0 * kFlow / (std::numbers::pi * kRadius * kRadius);
  double profile_error = 0.0;
  const int mid = grid.cells()[0] / 2;
  for (int k = 0; k < kCells; ++k) {
    for (int j = 0; j < kCells; ++j) {
      if (grid.kind(0, mid, j, k) != NodeKind::active) continue;
      const Vec3 p = grid.node_position_m(0, mid, j, k);
      const double exact = u_max * (1.0 - (p.y * p.y + p.z * p.z) / (kRadius * kRadius));
      profile_error = std::max(profile_error, std::abs(u(mid, j, k) - exact) / u_max);
    }
  }
  // Pressure: the Poiseuille gradient 8 mu Q / (pi R^4) between two cells on the axis a quarter of the tube from each
  // end, and the outlet's value on the outlet face (the last cell sits half a cell upstream of it).
  const int j0 = kCells / 2;
  const int i0 = grid.cells()[0] / 4;
  const int i1 = 3 * grid.cells()[0] / 4;
  const double dpdx = (solver.cell_pressure_Pa(i0, j0, j0) - solver.cell_pressure_Pa(i1, j0, j0)) / ((i1 - i0) * h);
  const double dpdx_exact = 8.0 * kRho * kNu * kFlow / (std::numbers::pi * std::pow(kRadius, 4));
  const double p_last = solver.cell_pressure_Pa(grid.cells()[0] - 1, j0, j0);
  const double p_face = p_last - 0.5 * h * dpdx;
  std::printf("open tube (openings): sections vs inlet max %.2e, outlet/inlet - 1 = %.2e, profile at L/2 vs "
              "Poiseuille(Q) %.2e of u_max, dp/dx / Poiseuille = %.4f, outlet face pressure %.4f Pa (asked %.1f)\n",
              worst, q_out / q_in - 1.0, profile_error, dpdx / dpdx_exact, p_face, kOutletPressure);
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(q_out / q_in, 1.0, 1e-3);   // the same conservation, through the opening's own counter
  EXPECT_LT(profile_error, 0.02);
  // The gradient follows the nodes' parabola, whose u_max the discrete-flux normalisation lowers by the cut faces'
  // excess (measured 0.9930 = 1 / 1.0070): the same cut-cell budget of 2% as the profile (and as the periodic tube's
  // flow-rate criterion, tube_poiseuille_test).
  EXPECT_NEAR(dpdx / dpdx_exact, 1.0, 0.02);
  // The face value extrapolated from the last cell with the tube's own gradient: the outlet's pressure to a fraction
  // of the drop over one cell (dpdx h = 0.3 Pa here).
  EXPECT_NEAR(p_face, kOutletPressure, 0.05 * dpdx * h);
}

}  // namespace
