// SPDX-License-Identifier: MIT
// Verification: periodic tube Poiseuille flow with Bouzidi bounce-back (accuracy, second-order convergence,
// wall shear stress from the non-equilibrium populations).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "lbm_test_helpers.hpp"

namespace hs::resolved {
namespace {

constexpr int kLength = 2;          // periodic tube length in nodes: the flow is axially invariant
constexpr double kUMax = 0.01;      // lattice centre-line speed, Mach 0.017
// With the corrected interpolated bounce-back the steady error does not depend on tau at fixed Lambda (checked
// below); tau = 1 is the textbook middle.
const CollisionParams kCollision{.model = CollisionModel::trt, .tau = 1.0, .magic = trt_magic_default};

struct TubeResult {
  double l2_error;          // || u - u_exact ||_2 / || u_exact ||_2 over the fluid nodes
  double wall_stress_lu;    // fitted sigma_rz at r = R
  double wall_stress_exact_lu;
};

/// Poiseuille in a tube: u_z(r) = g (R^2 - r^2) / (4 nu), wall shear stress rho g R / 2 (force balance).
TubeResult run_tube(double radius, const CollisionParams& collision = kCollision) {
  auto s = test::make_tube(radius, kLength, collision, WallRule::bouzidi, MPI_COMM_SELF);
  const double nu = collision.viscosity_lu();
  const double g = 4.0 * nu * kUMax / (radius * radius);
  const double c = s.centre_lu;
  s.lattice->set_body_force({0.0, 0.0, g});
  // Start from the analytic profile (inside the tube) to shorten the transient; the steady state is then
  // reached honestly by the residual criterion below.
  s.lattice->initialize([&](const common::Vec3& p) {
    const double r2 = (p.x - c) * (p.x - c) + (p.y - c) * (p.y - c);
    return NodeInit{.rho_lu = 1.0, .u_lu = {0.0, 0.0, std::max(0.0, g * (radius * radius - r2) / (4.0 * nu))}};
  });
  // Bouzidi bounce-back does not conserve mass, so the density (and with it u = j/rho) drifts slowly for ever,
  // by ~5e-7 of u per 100 steps here: the residual criterion must sit above that drift. At 1e-6 per 100 steps the
  // transient left (slowest decay time R^2/(5.78 nu) = 415 steps at R = 20) is < 1e-5 relative, far below the
  // discretisation error measured (> 4e-4).
  test::run_to_steady_state(*s.lattice, 1e-6, 100, 200000);
  const auto& l = s.lattice->layout();
  double err2 = 0.0, ref2 = 0.0, srr = 0.0, sr_sigma = 0.0;
  for (int y = 0; y < l.n[1]; ++y) {
    for (int x = 0; x < l.n[0]; ++x) {
      if (!s.lattice->is_fluid(x, y, 0)) continue;
      const double dx = x - c, dy = y - c, r = std::hypot(dx, dy);
      const double exact = g * (radius * radius - r * r) / (4.0 * nu);
      const auto m = s.lattice->moments(x, y, 0);
      err2 += (m.u.z - exact) * (m.u.z - exact) + m.u.x * m.u.x + m.u.y * m.u.y;
      ref2 += exact * exact;
      // sigma_rz = (x sigma_xz + y sigma_yz) / r is linear in r: fit sigma_rz = a r by least squares.
      const auto sigma = s.lattice->viscous_stress(x, y, 0);
      if (r > 0.0) {
        const double s_rz = (dx * sigma[4] + dy * sigma[5]) / r;
        srr += r * r;
        sr_sigma += r * s_rz;
      }
    }
  }
  return {std::sqrt(err2 / ref2), -(sr_sigma / srr) * radius, g * radius / 2.0};
}

/// Each radius is run once per test process.
const TubeResult& tube_result(double radius) {
  static std::map<double, TubeResult> cache;
  auto it = cache.find(radius);
  if (it == cache.end()) it = cache.emplace(radius, run_tube(radius)).first;
  return it->second;
}

TEST(TubePoiseuille, BouzidiErrorBelowOnePercentAtRadiusTen) {
  const TubeResult& r = tube_result(10.0);
  RecordProperty("l2_error_R10", std::to_string(r.l2_error));
  EXPECT_LT(r.l2_error, 0.01);   // acceptance of issue 2: < 1 % at R = 10 lattice spacings
}

TEST(TubePoiseuille, BouzidiConvergesAtSecondOrder) {
  const std::vector<double> radii{5.0, 10.0, 20.0};
  std::vector<double> lx, ly;
  for (const double r : radii) {
    const TubeResult& t = tube_result(r);
    lx.push_back(std::log(r));
    ly.push_back(std::log(t.l2_error));
  }
  // Least-squares slope of log(error) against log(R); the order is minus the slope.
  const double mx = (lx[0] + lx[1] + lx[2]) / 3.0, my = (ly[0] + ly[1] + ly[2]) / 3.0;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    sxy += (lx[k] - mx) * (ly[k] - my);
    sxx += (lx[k] - mx) * (lx[k] - mx);
  }
  const double order = -sxy / sxx;
  RecordProperty("fitted_order", std::to_string(order));
  EXPECT_GE(order, 1.8) << "errors " << std::exp(ly[0]) << " " << std::exp(ly[1]) << " " << std::exp(ly[2]);
}

TEST(TubePoiseuille, BouzidiErrorDoesNotDependOnTau) {
  // TRT at fixed Lambda with the corrected Bouzidi closure: the steady profile is the same for any tau. Plain
  // linear Bouzidi gave 0.17 % at tau = 1 and 0.92 % at tau = 2 here (a factor 5). The error itself is ~2e-3 of u;
  // the residual criterion and the slow mass drift of interpolated bounce-back leave ~1e-5 of u, i.e. up to 1 %
  // of the error: that is the tolerance on the ratio.
  const double at_one = tube_result(10.0).l2_error;
  const double at_three = run_tube(10.0, CollisionParams{.model = CollisionModel::trt, .tau = 3.0,
                                                         .magic = trt_magic_default}).l2_error;
  EXPECT_NEAR(at_three / at_one, 1.0, 1e-2) << at_one << " vs " << at_three;
}

TEST(TubePoiseuille, WallShearStressFromPopulationsWithinOnePercent) {
  const TubeResult& r = tube_result(10.0);
  RecordProperty("wall_stress_ratio", std::to_string(r.wall_stress_lu / r.wall_stress_exact_lu));
  // Issue 2 acceptance: the viscous stress from the populations equals the analytic wall stress within 1 %.
  EXPECT_NEAR(r.wall_stress_lu / r.wall_stress_exact_lu, 1.0, 0.01)
      << "fitted " << r.wall_stress_lu << " exact " << r.wall_stress_exact_lu;
}

}  // namespace
}  // namespace hs::resolved
