// SPDX-License-Identifier: MIT
// 2D lid-driven cavity at Re = 100 and 400 (one periodic cell in z) against Ghia, Ghia & Shin 1982 centrelines,
// and the Courant-number check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace {

using hs::common::Vec3;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;
using hs::unresolved::SideType;

/// The unit square in x and y, unbounded in z.
class Square final : public hs::common::Shape {
 public:
  [[nodiscard]] double signed_distance(const Vec3& p) const override {
    return std::max(std::abs(p.x - 0.5), std::abs(p.y - 0.5)) - 0.5;
  }
  [[nodiscard]] hs::common::Box3 bounds() const override { return {{0, 0, -1e9}, {1, 1, 1e9}}; }
};

FvmGridSpec cavity_spec(int n, double lid_m_s, int cells_in_z = 1) {
  const double h = 1.0 / n;
  FvmGridSpec spec{.box_m = {{0, 0, 0}, {1, 1, cells_in_z * h}}, .dx_m = h, .sides = {}};
  spec.sides[3].wall_velocity_m_s = {lid_m_s, 0, 0};   // lid at y = 1
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  return spec;
}

/// Runs the Re = 100 cavity to steady state with `coupling` and compares its centrelines with Ghia's.
void check_ghia_centrelines(hs::unresolved::PressureCoupling coupling) {
  const int n = 32;
  const Square square;
  const FvmGrid grid(square, cavity_spec(n, 1.0));
  // Re = U L / nu = 100; dt at Courant 0.5 on the lid speed; 25 lid time units reach the steady state
  // (the slowest decay time of the Re = 100 cavity is ~ 3 time units).
  FvmSolver solver(grid, {.density_kg_m3 = 1.0, .kinematic_viscosity_m2_s = 0.01}, {.dt_s = 0.5 / n, .coupling = coupling}, {});
  const long steps = static_cast<long>(25.0 * n / 0.5);
  for (long s = 0; s < steps; ++s) solver.step();
  const auto shared = std::string(HS_SOURCE_DIR) + "/data/reference/";
  const auto u_ref = hs::common::read_csv(shared + "ghia1982_cavity_u_vertical_centreline.csv");
  const auto v_ref = hs::common::read_csv(shared + "ghia1982_cavity_v_horizontal_centreline.csv");
  const double z = 0.5 / n;
  double worst_u = 0.0;
  double worst_v = 0.0;
  const auto y = u_ref.column("y");
  const auto u = u_ref.column("u_Re100");
  for (std::size_t q = 0; q < y.size(); ++q) worst_u = std::max(worst_u, std::abs(solver.velocity_at({0.5, y[q], z}).x - u[q]));
  const auto x = v_ref.column("x");
  const auto v = v_ref.column("v_Re100");
  for (std::size_t q = 0; q < x.size(); ++q) worst_v = std::max(worst_v, std::abs(solver.velocity_at({x[q], 0.5, z}).y - v[q]));
  std::printf("cavity Re=100, %d^2 cells: max |u - u_Ghia| = %.4f, max |v - v_Ghia| = %.4f (lid speed 1)\n", n, worst_u, worst_v);
  // Ghia's 129^2 solution agrees with later spectral results to ~1% of the lid speed (validation
  // README); our second-order central scheme at 32^2 adds an O(dx^2) error of about the same size near
  // the lid, so the band is 2% of the lid speed at every tabulated point (measured: 0.4% for u, 0.9% for v).
  EXPECT_LT(worst_u, 0.02);
  EXPECT_LT(worst_v, 0.02);
}

/// The steady cavity at Reynolds number re on n^2 cells: u on the vertical and v on the horizontal centreline at Ghia's
/// points.
struct Centrelines {
  std::vector<double> u, v;
};
Centrelines steady_cavity(int n, double re, const std::vector<double>& y, const std::vector<double>& x) {
  const Square square;
  const FvmGrid grid(square, cavity_spec(n, 1.0));
  // dt at Courant 0.8 on the lid speed (steady state only: the time error does not matter). 35 lid time units: the
  // slowest mode decays by ~20x per 10 units (centreline change 5e-3 from t = 20 to 30, 2e-4 from 30 to 40 at 48^2).
  FvmSolver solver(grid, {.density_kg_m3 = 1.0, .kinematic_viscosity_m2_s = 1.0 / re}, {.dt_s = 0.8 / n}, {});
  const long steps = static_cast<long>(35.0 * n / 0.8);
  for (long s = 0; s < steps; ++s) solver.step();
  const double z = 0.5 / n;
  Centrelines c;
  for (const double yq : y) c.u.push_back(solver.velocity_at({0.5, yq, z}).x);
  for (const double xq : x) c.v.push_back(solver.velocity_at({xq, 0.5, z}).y);
  return c;
}

/// Bound on the linear-interpolation error of velocity_at at each tabulated point on a grid of spacing h: h^2/8 |f''|,
/// with |f''| the largest second divided difference of Ghia's own profile over the point's neighbours.
std::vector<double> interpolation_bound(const std::vector<double>& s, const std::vector<double>& f, double h) {
  std::vector<double> curvature(s.size(), 0.0);
  for (std::size_t q = 1; q + 1 < s.size(); ++q) {
    const double d1 = (f[q + 1] - f[q]) / (s[q + 1] - s[q]);
    const double d0 = (f[q] - f[q - 1]) / (s[q] - s[q - 1]);
    curvature[q] = std::abs(2.0 * (d1 - d0) / (s[q + 1] - s[q - 1]));
  }
  std::vector<double> bound(s.size());
  for (std::size_t q = 0; q < s.size(); ++q) {
    const double c = std::max({curvature[q], q > 0 ? curvature[q - 1] : 0.0, q + 1 < s.size() ? curvature[q + 1] : 0.0});
    bound[q] = h * h / 8.0 * c;
  }
  return bound;
}

// Re = 400 against Ghia, Ghia & Shin 1982 (Tables I and II, Re = 400 columns). At Re = 400 the cell Reynolds number at
// 32^2 is 12.5 and the raw profiles are off by up to 2.5% of the lid speed: a grid error. The band is therefore applied
// to the grid-converged estimate, the Richardson extrapolation of 32^2 and 48^2 for the second-order central scheme,
// u_inf = u_48 + k (u_48 - u_32), k = 1 / ((48/32)^2 - 1). Band: 1% of the lid speed (Ghia's 129^2 multigrid solution
// agrees with later spectral results to about that, validation README), plus what the extrapolation cannot remove:
// sampling the profile between grid values is a linear interpolation whose error h^2/8 |u''| depends on where the point
// falls in a cell, not smoothly on h, so it enters as (1 + k) b_48 + k b_32. That matters only in the lid and wall
// layers (|u''| ~ 130 under the lid: +2.6%); elsewhere it is ~1e-3. A viscosity 10% off (Re 360 or 440) fails.
// Ghia's v = -0.23827 at x = 0.9063 is a suspected misprint (README): there the smooth profile must only lie between
// the tabulated neighbours v(0.9453) = -0.22847 and v(0.8594) = -0.44993.
/// One tabulated point of the Re = 400 comparison: the grid-converged value, Ghia's, and the band (see below).
struct GhiaPoint {
  char profile;   // 'u' or 'v'
  double s, value, ghia, band;
};

/// The cavity at Reynolds number re, Richardson-extrapolated from 32^2 and 48^2, at each of Ghia's Re = 400 points.
/// Ghia's misprinted v(0.9063) is left out (its own check is in the test).
std::vector<GhiaPoint> re400_comparison(double re, double* v_at_misprint = nullptr) {
  const auto shared = std::string(HS_SOURCE_DIR) + "/data/reference/";
  const auto u_ref = hs::common::read_csv(shared + "ghia1982_cavity_u_vertical_centreline.csv");
  const auto v_ref = hs::common::read_csv(shared + "ghia1982_cavity_v_horizontal_centreline.csv");
  const auto y = u_ref.column("y");
  const auto x = v_ref.column("x");
  const Centrelines coarse = steady_cavity(32, re, y, x);
  const Centrelines fine = steady_cavity(48, re, y, x);
  const double k = 1.0 / (1.5 * 1.5 - 1.0);
  std::vector<GhiaPoint> points;
  auto add = [&](char name, const std::vector<double>& s, const std::vector<double>& ghia, const std::vector<double>& f32,
                 const std::vector<double>& f48) {
    const auto b32 = interpolation_bound(s, ghia, 1.0 / 32.0);
    const auto b48 = interpolation_bound(s, ghia, 1.0 / 48.0);
    for (std::size_t q = 0; q < s.size(); ++q) {
      const double f_inf = f48[q] + k * (f48[q] - f32[q]);
      if (name == 'v' && std::abs(s[q] - 0.9063) < 1e-4) {
        if (v_at_misprint != nullptr) *v_at_misprint = f_inf;
        continue;
      }
      points.push_back({name, s[q], f_inf, ghia[q], 0.01 + (1.0 + k) * b48[q] + k * b32[q]});
    }
  };
  add('u', y, u_ref.column("u_Re400"), coarse.u, fine.u);
  add('v', x, v_ref.column("v_Re400"), coarse.v, fine.v);
  return points;
}

double worst_over_band(const std::vector<GhiaPoint>& points) {
  double worst = 0.0;
  for (const GhiaPoint& p : points) worst = std::max(worst, std::abs(p.value - p.ghia) / p.band);
  return worst;
}

TEST(CavityGhia, Re400CentrelinesMatchGhia1982OnTheConvergedGrid) {
  double v_misprint = 0.0;
  const std::vector<GhiaPoint> points = re400_comparison(400.0, &v_misprint);
  for (const GhiaPoint& p : points) EXPECT_NEAR(p.value, p.ghia, p.band) << p.profile << " at " << p.s;
  EXPECT_LT(v_misprint, -0.22847) << "v at the misprinted x = 0.9063";
  EXPECT_GT(v_misprint, -0.44993) << "v at the misprinted x = 0.9063";
  std::printf("cavity Re=400: v(0.9063) = %.4f (Ghia prints -0.23827)\n", v_misprint);
  std::printf("cavity Re=400, Richardson 32^2/48^2: max |f - f_Ghia| / band = %.2f\n", worst_over_band(points));
}

TEST(CavityGhia, NegativeControlAViscosityTenPercentOffLeavesTheRe400Band) {
  // The band above must see a 10% viscosity error: the cavity at Re 360 and at Re 440 against Ghia's Re 400 columns.
  for (const double re : {360.0, 440.0}) {
    const double worst = worst_over_band(re400_comparison(re));
    EXPECT_GT(worst, 1.0) << "Re " << re;
    std::printf("cavity Re=%.0f against Ghia's Re 400: max |f - f_Ghia| / band = %.2f\n", re, worst);
  }
}

TEST(CavityGhia, Re100CentrelinesMatchGhia1982) { check_ghia_centrelines(hs::unresolved::PressureCoupling::piso); }

// A recirculating flow whose pressure is far from uniform: the projection reaches the same steady state.
TEST(CavityGhia, Re100CentrelinesMatchGhia1982WithTheProjection) {
  check_ghia_centrelines(hs::unresolved::PressureCoupling::projection);
}

// The flow does not depend on z, so one periodic cell in z or two give the same velocities. With two, both z links
// of a node reach the same neighbour, whose matrix entry must hold both; keeping one (the pre-fix assembly) leaves
// the rows unbalanced: u off by 0.22 of the lid speed after a lid time unit (measured). Band: the momentum and pressure
// solves stop at relative residuals ~1e-6 and take different paths on the two grids (AMG coarsens them differently).
TEST(CavityGhia, TwoPeriodicCellsInZGiveTheOneCellFlow) {
  const int n = 16;
  const Square square;
  const auto run = [&](int cells_in_z) {
    const FvmGrid grid(square, cavity_spec(n, 1.0, cells_in_z));
    FvmSolver solver(grid, {.density_kg_m3 = 1.0, .kinematic_viscosity_m2_s = 0.01}, {.dt_s = 0.5 / n}, {});
    for (int s = 0; s < 2 * n; ++s) solver.step();   // one lid time unit
    std::vector<Vec3> u;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) u.push_back(solver.velocity_at({(i + 0.5) / n, (j + 0.5) / n, 0.5 / n}));
    }
    return u;
  };
  const std::vector<Vec3> one = run(1);
  const std::vector<Vec3> two = run(2);
  double worst = 0.0;
  for (std::size_t q = 0; q < one.size(); ++q) {
    worst = std::max({worst, std::abs(one[q].x - two[q].x), std::abs(one[q].y - two[q].y), std::abs(two[q].z)});
  }
  std::printf("cavity, one vs two periodic cells in z: max |u1 - u2| = %.2e (lid speed 1)\n", worst);
  EXPECT_LT(worst, 1e-4);
}

TEST(CavityGhia, CourantViolationIsANumericalError) {
  const int n = 16;
  const Square square;
  const FvmGrid grid(square, cavity_spec(n, 1.0));
  // dt = 4 dx / U_lid: the lid-adjacent velocity soon exceeds max_courant = 1.
  FvmSolver solver(grid, {.density_kg_m3 = 1.0, .kinematic_viscosity_m2_s = 0.01}, {.dt_s = 4.0 / n, .max_courant = 1.0}, {});
  try {
    for (int s = 0; s < 20; ++s) solver.step();
    FAIL() << "expected a Courant violation";
  } catch (const hs::common::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("Courant number"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reduce dt_s"), std::string::npos) << e.what();
  }
}

TEST(CavityGhia, BadGridIsAConfigError) {
  const Square square;
  FvmGridSpec spec = cavity_spec(16, 1.0);
  spec.dx_m = 0.3;   // 1 / 0.3 is not a whole number of cells
  EXPECT_THROW(FvmGrid(square, spec), hs::common::ConfigError);
  spec = cavity_spec(16, 1.0);
  spec.sides[5].type = SideType::wall;   // periodic on one side only
  EXPECT_THROW(FvmGrid(square, spec), hs::common::ConfigError);
}

}  // namespace
