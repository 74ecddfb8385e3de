// SPDX-License-Identifier: MIT
// Verification of the lattice's second fluid phase (the cytoplasm): layered Couette and Poiseuille flows with a
// viscosity jump against their analytic profiles, and one phase of equal viscosity bit for bit the single-phase path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lbm_test_helpers.hpp"

namespace hs::resolved {
namespace {

struct Layered {
  CollisionModel model;
  double tau_out;
  double ratio;     // inner / outer dynamic viscosity
  int width = 16;   // channel width H (half-way walls at y = -1/2 and H - 1/2), a multiple of 16
  /// The inner phase: nodes y = lo..hi, 5 H / 16 .. H - 1 - 5 H / 16, symmetric about the centre line; the
  /// interfaces lie half way between the phases' nodes, at lo - 1/2 and hi + 1/2.
  [[nodiscard]] int lo() const { return 5 * width / 16; }
  [[nodiscard]] int hi() const { return width - 1 - lo(); }
};

CollisionParams phase(CollisionModel model, double tau) {
  return CollisionParams{.model = model, .tau = tau, .magic = trt_magic_default};
}

/// Channel with the middle layer as the inner phase, two-buffer or AA streaming.
std::unique_ptr<FluidLattice> layered_channel(const Layered& p, Streaming streaming) {
  const CollisionParams out = phase(p.model, p.tau_out);
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {2, p.width, 2}, .periodic = {true, false, true}, .collision = out,
                  .rho0_lu = 1.0, .streaming = streaming},
      MPI_COMM_SELF);
  lattice->set_inner_collision(phase(p.model, 0.5 + p.ratio * (p.tau_out - 0.5)));
  return lattice;
}

void mark_middle_layer(FluidLattice& lattice, const Layered& p) {
  std::vector<std::ptrdiff_t> inner;
  for (int y = p.lo(); y <= p.hi(); ++y) {
    for (int x = 0; x < 2; ++x) {
      for (int z = 0; z < 2; ++z) inner.push_back(lattice.layout().index(x, y, z));
    }
  }
  lattice.set_inner_nodes(inner);
}

/// Couette, bottom wall at rest, top at u_w: the shear stress is uniform, so u' = tau / mu piecewise and
/// u(y) = u_w * (integral from -1/2 to y of 1/mu) / (integral over the gap of 1/mu).
double couette_error(const Layered& p, Streaming streaming) {
  auto lattice = layered_channel(p, streaming);
  const double u_wall = 0.01;
  lattice->set_face_wall_velocity(1, 1, {u_wall, 0.0, 0.0});
  lattice->initialize();
  mark_middle_layer(*lattice, p);
  test::run_to_steady_state(*lattice, 1e-14, 200, 1000000);
  const auto compliance = [&](double y) {   // integral of 1/mu from the bottom wall to y, exact for the layers
    double sum = 0.0;
    const double lo = p.lo() - 0.5, hi = p.hi() + 0.5;
    sum += std::min(y, lo) + 0.5;
    if (y > lo) sum += (std::min(y, hi) - lo) / p.ratio;
    if (y > hi) sum += y - hi;
    return sum;
  };
  double worst = 0.0;
  for (int y = 0; y < p.width; ++y) {
    const double exact = u_wall * compliance(y) / compliance(p.width - 0.5);
    const auto m = lattice->moments(1, y, 1);
    worst = std::max({worst, std::abs(m.u.x - exact) / u_wall, std::abs(m.u.y) / u_wall});
  }
  return worst;
}

/// Plane Poiseuille driven by g, the inner layer symmetric about the centre line y_c = (H - 1)/2: the stress is
/// g (y_c - y) everywhere, so u(y) = g / nu_out * integral from -1/2 to y of (y_c - s) / mu_rel(s) ds, piecewise
/// quadratic. Returned relative to the centre-line speed.
double poiseuille_error(const Layered& p, Streaming streaming) {
  auto lattice = layered_channel(p, streaming);
  const double nu_out = (p.tau_out - 0.5) / 3.0;
  const double g = 1e-5 * nu_out;   // u_max ~ g H^2 / (8 nu): ~3e-4 at ratio 1, Mach far below the limit
  lattice->set_body_force({g, 0.0, 0.0});
  lattice->initialize();
  mark_middle_layer(*lattice, p);
  test::run_to_steady_state(*lattice, 1e-14, 200, 1000000);
  const double yc = 0.5 * (p.width - 1);
  const auto exact = [&](double y) {   // piecewise integral of (y_c - s) / mu_rel(s)
    const double lo = p.lo() - 0.5, hi = p.hi() + 0.5;
    const auto prim = [&](double a, double b) { return yc * (b - a) - 0.5 * (b * b - a * a); };
    double u = prim(-0.5, std::min(y, lo));
    if (y > lo) u += prim(lo, std::min(y, hi)) / p.ratio;
    if (y > hi) u += prim(hi, y);
    return g / nu_out * u;
  };
  const double u_centre = exact(yc);
  double worst = 0.0;
  for (int y = 0; y < p.width; ++y) {
    const auto m = lattice->moments(1, y, 1);
    worst = std::max({worst, std::abs(m.u.x - exact(y)) / u_centre, std::abs(m.u.y) / u_centre});
  }
  return worst;
}

std::string layered_name(const ::testing::TestParamInfo<Layered>& param_info) {
  const Layered& p = param_info.param;
  return std::string(collision_model_name(p.model)) + "_tau" + std::to_string(static_cast<int>(10 * p.tau_out)) +
         "_ratio" + std::to_string(static_cast<int>(100 * p.ratio));
}

/// Couette is piecewise linear: every operator, with the viscosity jumping between the last node of one phase and the
/// first of the other, puts the interface exactly half way, and the profile is exact to round-off (bound 1e-10, as
/// the single-phase channel tests; measured 6e-14 to 1.2e-11; the campaign's tau 12.5 at ratio 4.86, inner tau 58.8,
/// gave 5.1e-11 in 21 s and is left out for time).
class LayeredCouette : public ::testing::TestWithParam<Layered> {};

TEST_P(LayeredCouette, MatchesTheLayeredProfile) {
  EXPECT_LT(couette_error(GetParam(), Streaming::two_buffer), 1e-10);
  EXPECT_LT(couette_error(GetParam(), Streaming::aa), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Phases, LayeredCouette,
                         ::testing::Values(Layered{CollisionModel::trt, 0.8, 5.0}, Layered{CollisionModel::trt, 2.0, 0.2},
                                           Layered{CollisionModel::bgk, 1.0, 5.0},
                                           Layered{CollisionModel::regularized, 2.0, 10.0},   // TRT out (2), regularised in (15.5)
                                           Layered{CollisionModel::regularized, 5.0, 5.0}),   // regularised both (5, 22.5)
                         layered_name);

/// Poiseuille (piecewise quadratic) with TRT: both phases keep Lambda = 3/16, and the layered profile is exact to
/// round-off as the single-phase one (bound 1e-10; measured 1.2e-12 to 5.5e-12).
class LayeredPoiseuilleTrt : public ::testing::TestWithParam<Layered> {};

TEST_P(LayeredPoiseuilleTrt, MatchesTheLayeredProfile) {
  EXPECT_LT(poiseuille_error(GetParam(), Streaming::two_buffer), 1e-10);
  EXPECT_LT(poiseuille_error(GetParam(), Streaming::aa), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Phases, LayeredPoiseuilleTrt,
                         ::testing::Values(Layered{CollisionModel::trt, 1.0, 5.0}, Layered{CollisionModel::trt, 1.0, 0.4}),
                         layered_name);

/// The regularised collision's odd rate is bounded, so its Lambda grows with tau (collision_params.hpp) and differs
/// between the phases; where u'' jumps (Poiseuille, not Couette) the interface then sits off half way by O(Lambda) dx,
/// an error falling as 1 / H^2 relative to the centre-line speed. Measured at H = 16: 1.5e-3 (TRT tau 2 outside,
/// regularised 15.5 inside), 3.5e-3 (regularised 5 and 22.5). Checked: second order, the error at least 3x smaller
/// at twice the width (an order >= 1.58; 4x is exact second order), and below 1 % at H = 16.
TEST(LayeredPoiseuilleRegularized, InterfaceErrorIsSecondOrder) {
  // Measured: 1.540e-3 at H = 16, 3.851e-4 at H = 32 (ratio 4.00).
  const double e16 = poiseuille_error(Layered{CollisionModel::regularized, 2.0, 10.0, 16}, Streaming::aa);
  const double e32 = poiseuille_error(Layered{CollisionModel::regularized, 2.0, 10.0, 32}, Streaming::aa);
  EXPECT_LT(e16, 1e-2);
  EXPECT_GT(e16 / e32, 3.0) << "H = 16: " << e16 << ", H = 32: " << e32;
}

/// The machinery of two phases (runs split by phase, per-run rates) with equal viscosities must not change one bit:
/// a channel with a force field and the nodes of a ball as phase 1 of the same collision, against the one-phase
/// lattice, for each operator and both streaming schemes.
void expect_equal_phases_change_nothing(CollisionModel model, double tau, Streaming streaming) {
  const CollisionParams collision = phase(model, tau);
  const auto make = [&] {
    auto lattice = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {12, 10, 8}, .periodic = {true, false, true}, .collision = collision,
                    .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    lattice->set_body_force({2e-6, 0.0, 0.0});
    lattice->set_face_wall_velocity(1, 1, {0.01, 0.0, 0.0});
    lattice->enable_force_field();
    lattice->initialize();
    for (int x = 3; x < 9; ++x) lattice->add_force(x, 4, 3, {1e-4 * x, -2e-5, 3e-5});
    return lattice;
  };
  auto one = make();
  auto two = make();
  two->set_inner_collision(collision);
  std::vector<std::ptrdiff_t> ball;
  for (int x = 0; x < 12; ++x) {
    for (int y = 0; y < 10; ++y) {
      for (int z = 0; z < 8; ++z) {
        if ((x - 6) * (x - 6) + (y - 5) * (y - 5) + (z - 4) * (z - 4) <= 9) ball.push_back(two->layout().index(x, y, z));
      }
    }
  }
  two->set_inner_nodes(ball);
  ASSERT_EQ(two->inner_node_count(), ball.size());
  one->run(41);
  two->run(41);
  const auto a = one->raw_populations();
  const auto b = two->raw_populations();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin())) << collision_model_name(model) << " tau " << tau;
}

/// The same through a tube with Bouzidi walls, phase 1 whole cross-sections (z = 2..4), so that the runs the AA kernel
/// keeps wall-link odd parts for are split too (FluidRun::odd_parts carried into the pieces).
void expect_equal_phases_change_nothing_in_a_tube(CollisionModel model, double tau, Streaming streaming) {
  const CollisionParams collision = phase(model, tau);
  const common::Tube tube(common::TubeSpec{.start_m = {6.0, 6.0, -1.0}, .end_m = {6.0, 6.0, 9.0}, .radius_m = 4.3});
  const auto make = [&] {
    auto lattice = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {13, 13, 8}, .periodic = {false, false, true}, .collision = collision,
                    .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    lattice->set_shape(tube, ShapePlacement{.origin = {}, .spacing = 1.0}, WallRule::bouzidi);
    lattice->set_body_force({0.0, 0.0, 1e-6});
    lattice->initialize();
    return lattice;
  };
  auto one = make();
  auto two = make();
  two->set_inner_collision(collision);
  std::vector<std::ptrdiff_t> slab;
  const auto& n = two->layout().n;
  for (int x = 0; x < n[0]; ++x) {
    for (int y = 0; y < n[1]; ++y) {
      for (int z = 2; z <= 4; ++z) slab.push_back(two->layout().index(x, y, z));
    }
  }
  two->set_inner_nodes(slab);
  one->run(37);
  two->run(37);
  const auto a = one->raw_populations();
  const auto b = two->raw_populations();
  EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin())) << collision_model_name(model) << " tau " << tau;
}

TEST(TwoPhases, EqualViscositiesAreTheOnePhaseLatticeBitForBit) {
  for (const Streaming s : {Streaming::two_buffer, Streaming::aa}) {
    expect_equal_phases_change_nothing(CollisionModel::trt, 0.9, s);
    expect_equal_phases_change_nothing(CollisionModel::bgk, 0.9, s);
    expect_equal_phases_change_nothing(CollisionModel::regularized, 8.0, s);
    expect_equal_phases_change_nothing_in_a_tube(CollisionModel::trt, 0.9, s);
    expect_equal_phases_change_nothing_in_a_tube(CollisionModel::regularized, 8.0, s);
  }
}

}  // namespace
}  // namespace hs::resolved
