// SPDX-License-Identifier: MIT
// Verification of CollisionModel::regularized (issue #27): planar Poiseuille and Couette exact at tau 0.6-60, tube
// Poiseuille with Bouzidi walls as accurate as TRT at tau 60, mass and momentum conserved to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "lbm_test_helpers.hpp"

namespace hs::resolved {
namespace {

constexpr int kWidth = 8;
constexpr double kUMax = 0.01;

CollisionParams regularized(double tau) { return {.model = CollisionModel::regularized, .tau = tau}; }

/// A plane slab of fluid between y = lo and y = hi (Bouzidi walls off the lattice midplanes).
class Slab final : public common::Shape {
 public:
  Slab(double lo, double hi) : lo_(lo), hi_(hi) {}
  [[nodiscard]] double signed_distance(const common::Vec3& p) const override { return std::max(lo_ - p.y, p.y - hi_); }
  [[nodiscard]] common::Box3 bounds() const override { return {{-1e9, lo_, -1e9}, {1e9, hi_, 1e9}}; }

 private:
  double lo_, hi_;
};

/// Worst velocity error / u_max of plane Poiseuille (drive g) or Couette (top wall at u_w) in a channel whose first and
/// last fluid nodes are y = 0 and kWidth - 1. q < 0: half-way face walls; else Bouzidi walls at fractions q, q_top.
double channel_error(double tau, bool couette, double q, double q_top) {
  const bool faces = q < 0.0;
  const double lo = faces ? -0.5 : -q;
  const double hi = faces ? kWidth - 0.5 : kWidth - 1 + q_top;
  const Slab slab(lo, hi);
  const int ny = faces ? kWidth : kWidth + 2;
  FluidLattice lattice(LatticeSpec{.global_nodes = {2, ny, 2}, .periodic = {true, false, true},
                                   .collision = regularized(tau)},
                       MPI_COMM_SELF);
  if (!faces) lattice.set_shape(slab, ShapePlacement{.origin = {0.0, -1.0, 0.0}, .spacing = 1.0}, WallRule::bouzidi);
  const double nu = lattice.collision().viscosity_lu();
  const double g = 8.0 * nu * kUMax / ((hi - lo) * (hi - lo));
  if (couette) {
    lattice.set_face_wall_velocity(1, 1, {kUMax, 0.0, 0.0});
  } else {
    lattice.set_body_force({g, 0.0, 0.0});
  }
  lattice.initialize();
  // Residual 1e-14 per block: the transient left is four orders below the 1e-10 acceptance.
  test::run_to_steady_state(lattice, 1e-14, 200, 400000);
  double worst = 0.0;
  for (int j = faces ? 0 : 1; j < (faces ? kWidth : kWidth + 1); ++j) {
    const double y = faces ? j : j - 1.0;
    const double exact = couette ? kUMax * (y - lo) / (hi - lo) : g / (2.0 * nu) * (y - lo) * (hi - y);
    const auto m = lattice.moments(0, j, 0);
    worst = std::max({worst, std::abs(m.u.x - exact) / kUMax, std::abs(m.u.y) / kUMax});
  }
  return worst;
}

class RegularizedTau : public ::testing::TestWithParam<double> {};

// Planar walls: the shifted closure (boundary_links.hpp) closes as TRT at Lambda = 3/16, which is exact for the
// parabola on half-way walls and, with the interpolation correction, at any wall fraction; the linear profile is
// exact for any closure. Only round-off remains, at every tau the campaign and an inner fluid at ratio 5 ask for.
TEST_P(RegularizedTau, HalfWayPoiseuilleIsExact) { EXPECT_LT(channel_error(GetParam(), false, -1.0, 0.0), 1e-10); }
TEST_P(RegularizedTau, BouzidiPoiseuilleIsExact) { EXPECT_LT(channel_error(GetParam(), false, 0.25, 0.8), 1e-10); }
TEST_P(RegularizedTau, CouetteIsExact) { EXPECT_LT(channel_error(GetParam(), true, -1.0, 0.0), 1e-10); }

INSTANTIATE_TEST_SUITE_P(Taus, RegularizedTau, ::testing::Values(0.6, 1.0, 5.0, 15.0, 30.0, 60.0));

/// L2 error of tube Poiseuille with Bouzidi walls (as tube_test.cpp). The drive is set after initialize(), as the case
/// runners ramp it: the closures read the body force of each step.
double tube_error(double radius, const CollisionParams& collision, Streaming streaming = Streaming::two_buffer) {
  const int n = static_cast<int>(std::ceil(2.0 * radius)) + 4;
  const double c = 0.5 * (n - 1);
  const common::Tube tube(common::TubeSpec{.start_m = {c, c, -1.0}, .end_m = {c, c, 3.0}, .radius_m = radius});
  auto lattice = std::make_unique<FluidLattice>(LatticeSpec{.global_nodes = {n, n, 2}, .periodic = {false, false, true},
                                                            .collision = collision, .streaming = streaming},
                                                MPI_COMM_SELF);
  lattice->set_shape(tube, ShapePlacement{.origin = {}, .spacing = 1.0}, WallRule::bouzidi);
  const test::TubeSetup s{.shape = nullptr, .lattice = std::move(lattice), .centre_lu = c};
  const double nu = collision.viscosity_lu();
  const double g = 4.0 * nu * kUMax / (radius * radius);
  const auto exact = [&](double x, double y) {
    return std::max(0.0, g * (radius * radius - (x - c) * (x - c) - (y - c) * (y - c)) / (4.0 * nu));
  };
  s.lattice->initialize([&](const common::Vec3& p) { return NodeInit{.rho_lu = 1.0, .u_lu = {0.0, 0.0, exact(p.x, p.y)}}; });
  s.lattice->set_body_force({0.0, 0.0, g});
  // As tube_test.cpp: 1e-6 per 100 steps sits above the slow mass drift of interpolated bounce-back and leaves a
  // transient far below the discretisation error (> 5e-4).
  test::run_to_steady_state(*s.lattice, 1e-6, 100, 200000);
  double err2 = 0.0, ref2 = 0.0;
  const auto& l = s.lattice->layout();
  for (int y = 0; y < l.n[1]; ++y) {
    for (int x = 0; x < l.n[0]; ++x) {
      if (!s.lattice->is_fluid(x, y, 0)) continue;
      const auto m = s.lattice->moments(x, y, 0);
      const double e = exact(x, y);
      err2 += (m.u.z - e) * (m.u.z - e) + m.u.x * m.u.x + m.u.y * m.u.y;
      ref2 += e * e;
    }
  }
  return std::sqrt(err2 / ref2);
}

// Curved walls at tau 60 (an inner fluid at viscosity ratio 5 in the campaign): the bounded odd rate gives Lambda =
// 3.3, whose wall shift the closure removes to second order. Measured (R = 5 / 10 / 20): regularized 5.8e-2 / 2.1e-3 /
// 5.42e-4, TRT 5.3e-3 / 2.15e-3 / 5.41e-4. Acceptance: at R = 20 (the campaign's R = 25 um at dx = 1 um) the error is
// TRT's within 1 % (the residual criterion leaves ~1e-5 of u, 2 % of the error: 1 % is what the two runs, stopped the
// same way, agree to), and the order from R = 10 to 20 is at least 1.8 as the tube tests ask of TRT.
TEST(RegularizedTube, AsAccurateAsTrtAtTauSixty) {
  const double reg10 = tube_error(10.0, regularized(60.0));
  const double reg20 = tube_error(20.0, regularized(60.0));
  const double trt20 = tube_error(20.0, CollisionParams{.model = CollisionModel::trt, .tau = 60.0});
  RecordProperty("regularized_R10", std::to_string(reg10));
  RecordProperty("regularized_R20", std::to_string(reg20));
  RecordProperty("trt_R20", std::to_string(trt20));
  EXPECT_LT(reg20, 1.01 * trt20) << reg20 << " vs TRT " << trt20;
  EXPECT_GE(std::log(reg10 / reg20) / std::log(2.0), 1.8) << reg10 << " " << reg20;
}

// The in-place AA kernel runs the same collision and closures: the steady error matches the two-buffer one (the two
// differ by round-off per step and stop by the same residual criterion, 1e-6 per 100 steps of ~5e-4 -> 1e-3 relative).
TEST(RegularizedTube, AaMatchesTwoBuffer) {
  const double two = tube_error(10.0, regularized(30.0));
  const double aa = tube_error(10.0, regularized(30.0), Streaming::aa);
  EXPECT_NEAR(aa / two, 1.0, 1e-3) << aa << " vs " << two;
}

/// Amplitude ratio over `steps` of a shear wave u_y = A sin(k x) carried by a uniform flow u_x = U along a periodic
/// row of `kRow` nodes, projected on the wave advected with U.
constexpr int kRow = 256;
double shear_wave_decay(double tau, double u_carrier, long steps) {
  FluidLattice lattice(LatticeSpec{.global_nodes = {kRow, 2, 2}, .periodic = {true, true, true},
                                   .collision = regularized(tau)},
                       MPI_COMM_SELF);
  const double k = 2.0 * std::numbers::pi / kRow;
  const double amplitude = 1e-3;
  lattice.initialize([&](const common::Vec3& p) {
    return NodeInit{.rho_lu = 1.0, .u_lu = {u_carrier, amplitude * std::sin(k * p.x), 0.0}};
  });
  lattice.run(steps);
  double proj = 0.0;
  const double shift = u_carrier * static_cast<double>(steps);
  for (int x = 0; x < kRow; ++x) proj += lattice.moments(x, 0, 0).u.y * std::sin(k * (x - shift));
  return proj / (0.5 * kRow * amplitude);
}

// Galilean invariance at tau 30: a carrier flow at Mach 0.09 leaves the decay of the shear wave unchanged up to the
// O(Ma^2) defect of the second-order equilibrium (Ma^2 = 0.0075: the tolerance, 1e-2). Measured: carried / at rest =
// 1.0050. (Against exp(-nu k^2 t) both decay 12.6 % slower over 100 steps: at tau 30 the stress of a flow started at
// equilibrium builds up over ~tau - 1/2 steps, as for any operator with this viscosity: a Maxwell lag, not a defect.)
TEST(RegularizedGalilean, CarrierFlowLeavesShearWaveDecayUnchanged) {
  constexpr double kTau = 30.0;
  constexpr long kSteps = 100;
  const double at_rest = shear_wave_decay(kTau, 0.0, kSteps);
  const double carried = shear_wave_decay(kTau, 0.05, kSteps);
  RecordProperty("carried_over_at_rest", std::to_string(carried / at_rest));
  EXPECT_NEAR(carried / at_rest, 1.0, 1e-2);
}

// Mass and momentum: the collision conserves rho and adds exactly F to j (Guo), so in a periodic box with a force on
// one node the totals follow M(t) = M(0) and J(t) = J(0) + t F to round-off (1e-12 relative over 200 steps).
TEST(RegularizedConservation, MassAndMomentumToRoundOff) {
  FluidLattice lattice(LatticeSpec{.global_nodes = {8, 8, 8}, .periodic = {true, true, true},
                                   .collision = regularized(30.0)},
                       MPI_COMM_SELF);
  lattice.enable_force_field();
  lattice.initialize([](const common::Vec3& p) {
    return NodeInit{.rho_lu = 1.0 + 0.01 * std::sin(p.x), .u_lu = {0.01 * std::cos(p.y), 0.005 * std::sin(p.z), 0.0}};
  });
  const common::Vec3 force{1e-3, -2e-3, 5e-4};
  const auto totals = [&](double& mass, common::Vec3& j) {
    mass = 0.0;
    j = {};
    for (int z = 0; z < 8; ++z) {
      for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
          const auto m = lattice.moments(x, y, z);
          mass += m.rho;
          j += m.rho * m.u - 0.5 * lattice.force(x, y, z);   // sum f c
        }
      }
    }
  };
  double m0 = 0.0;
  common::Vec3 j0;
  totals(m0, j0);
  constexpr int kSteps = 200;
  for (int s = 0; s < kSteps; ++s) {
    lattice.clear_force_field();
    lattice.add_force(3, 4, 5, force);
    lattice.step();
  }
  double m1 = 0.0;
  common::Vec3 j1;
  totals(m1, j1);
  EXPECT_NEAR(m1 / m0, 1.0, 1e-12);
  const common::Vec3 expected = j0 + static_cast<double>(kSteps) * force;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(j1[a], expected[a], 1e-12 * m0) << "axis " << a;
}

}  // namespace
}  // namespace hs::resolved
