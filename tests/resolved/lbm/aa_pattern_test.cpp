// SPDX-License-Identifier: MIT
// Verification: the in-place AA pattern gives the same populations as the two-buffer pull scheme after even and odd
// step counts (periodic box with forces, half-way walls with a moving wall, Bouzidi tubes on one and two threads), and
// plane Poiseuille.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "lbm_test_helpers.hpp"

namespace hs::resolved {
namespace {

const CollisionParams kTrt{.model = CollisionModel::trt, .tau = 0.8, .magic = trt_magic_default};

/// Smooth, non-uniform initial state, so every direction carries a different value across every face.
NodeInit swirl(const common::Vec3& p) {
  return NodeInit{.rho_lu = 1.0 + 0.002 * std::sin(0.7 * p.x + 0.3 * p.z),
                  .u_lu = {0.004 * std::cos(0.5 * p.y), 0.003 * std::sin(0.4 * p.z), 0.005 * std::cos(0.3 * p.x)}};
}

using Maker = std::function<std::unique_ptr<FluidLattice>(Streaming)>;

/// The watchdog reads the populations in place, not through population(): with the Mach limit just below the largest
/// lattice Mach number of moments() it must name that node, just above it stay quiet (both AA layouts, x wrapping).
void expect_watchdog_reads_the_layout(const FluidLattice& lattice) {
  const auto& l = lattice.layout();
  double worst = 0.0;
  std::string node;
  for (int z = 0; z < l.n[2]; ++z) {
    for (int y = 0; y < l.n[1]; ++y) {
      for (int x = 0; x < l.n[0]; ++x) {
        if (!lattice.is_fluid(x, y, z)) continue;
        const double mach = norm(lattice.moments(x, y, z).u) / std::sqrt(D3Q19::cs2);
        if (mach > worst) {
          worst = mach;
          node = fmt::format("node ({}, {}, {})", x, y, z);
        }
      }
    }
  }
  // 1e-9 relative: far above the round-off of summing 19 populations in another order, far below the spread of Mach
  // numbers between nodes of these smooth fields.
  EXPECT_NO_THROW(lattice.check_health(HealthLimits{.mach_max = worst * (1.0 + 1e-9)}));
  try {
    lattice.check_health(HealthLimits{.mach_max = worst * (1.0 - 1e-9)});
    ADD_FAILURE() << "the watchdog missed " << node;
  } catch (const common::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find(node), std::string::npos) << e.what();
  }
}

/// Largest relative difference of any pre-collision population of any fluid node between the two schemes after
/// `steps` steps; also checks that moments() and viscous_stress() agree (they read populations through the scheme).
double max_relative_difference(const Maker& make, long steps) {
  auto two = make(Streaming::two_buffer);
  auto aa = make(Streaming::aa);
  two->run(steps);
  aa->run(steps);
  const auto& l = two->layout();
  double worst = 0.0;
  for (int z = 0; z < l.n[2]; ++z) {
    for (int y = 0; y < l.n[1]; ++y) {
      for (int x = 0; x < l.n[0]; ++x) {
        if (!two->is_fluid(x, y, z)) continue;
        for (int i = 0; i < D3Q19::q; ++i) {
          const double ref = two->population(x, y, z, i);
          worst = std::max(worst, std::abs(aa->population(x, y, z, i) - ref) / std::abs(ref));
        }
        // The stress sums 19 populations (<= 1/3) with O(1) weights: their few-ulp differences stay below 1e-14.
        const auto s_two = two->viscous_stress(x, y, z);
        const auto s_aa = aa->viscous_stress(x, y, z);
        for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(s_two[k], s_aa[k], 1e-14);
      }
    }
  }
  EXPECT_NEAR(two->total_mass(), aa->total_mass(), 1e-13 * two->total_mass());
  expect_watchdog_reads_the_layout(*aa);
  ::testing::Test::RecordProperty("max_relative_difference", fmt::format("{:.3g}", worst));
  return worst;
}

// Both schemes run the same collision (trt_guo_collide) on the same values; bounce-back and halo passes only copy
// or combine values in the same order. 1e-13 relative allows for the compiler contracting a multiply-add
// differently in the two kernels' vectorised loops (a few ulps per step).
constexpr double kTolerance = 1e-13;

class AaSteps : public ::testing::TestWithParam<long> {};

TEST_P(AaSteps, PeriodicBoxWithBodyForceAndForceFieldMatchesTwoBuffer) {
  const Maker make = [](Streaming streaming) {
    auto l = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {12, 10, 9}, .periodic = {true, true, true}, .collision = kTrt,
                    .ranks_per_axis = {}, .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    l->enable_force_field();
    l->set_body_force({2e-5, -1e-5, 3e-6});
    l->initialize(swirl);
    for (int z = 0; z < 9; ++z) l->add_force(3, z % 10, z, {1e-4, 0.0, -2e-4});   // a local field, as the IBM spreads
    return l;
  };
  EXPECT_LT(max_relative_difference(make, GetParam()), kTolerance);
}

TEST_P(AaSteps, HalfWayChannelWithMovingWallMatchesTwoBuffer) {
  const Maker make = [](Streaming streaming) {
    auto l = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {6, 8, 5}, .periodic = {true, false, true}, .collision = kTrt,
                    .ranks_per_axis = {}, .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    l->set_face_wall_velocity(1, 1, {0.01, 0.0, 0.002});
    l->set_body_force({1e-5, 0.0, 0.0});
    l->initialize(swirl);
    return l;
  };
  EXPECT_LT(max_relative_difference(make, GetParam()), kTolerance);
}

TEST_P(AaSteps, BouzidiTubeMatchesTwoBuffer) {
  // Radius 4.3 lattice spacings, axis at the centre of a 13^2 cross-section, periodic along x, where the AA kernel
  // wraps x itself (no x ghosts): links that cross the periodic face into the wall are closed through the wrap.
  const double c = 6.0;
  const common::Tube tube(common::TubeSpec{.start_m = {-1.0, c, c}, .end_m = {7.0, c, c}, .radius_m = 4.3});
  const Maker make = [&](Streaming streaming) {
    const CollisionParams collision{.model = CollisionModel::trt, .tau = 1.3, .magic = trt_magic_default};
    auto l = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {6, 13, 13}, .periodic = {true, false, false}, .collision = collision,
                    .ranks_per_axis = {}, .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    l->set_shape(tube, ShapePlacement{.origin = {}, .spacing = 1.0}, WallRule::bouzidi);
    l->set_body_force({1e-5, 1e-6, 0.0});
    l->initialize(swirl);
    return l;
  };
  EXPECT_LT(max_relative_difference(make, GetParam()), kTolerance);
}

TEST_P(AaSteps, BouzidiTubeOnTwoThreadsMatchesTwoBuffer) {
  // Radius 22 along a periodic z, 36k fluid nodes: enough for the kernels to share the work among threads (two here),
  // which for AA means contiguous ranges of z layers whose wall links are applied inside the kernel, the first and
  // last layer of each range after the other thread's layers are done.
  const double c = 23.5;
  const common::Tube tube(common::TubeSpec{.start_m = {c, c, -1.0}, .end_m = {c, c, 25.0}, .radius_m = 22.0});
  const Maker make = [&](Streaming streaming) {
    const CollisionParams collision{.model = CollisionModel::trt, .tau = 0.9, .magic = trt_magic_default};
    auto l = std::make_unique<FluidLattice>(
        LatticeSpec{.global_nodes = {48, 48, 24}, .periodic = {false, false, true}, .collision = collision,
                    .ranks_per_axis = {}, .rho0_lu = 1.0, .streaming = streaming},
        MPI_COMM_SELF);
    l->set_shape(tube, ShapePlacement{.origin = {}, .spacing = 1.0}, WallRule::bouzidi);
    l->set_body_force({1e-6, 2e-6, 1e-5});
    l->initialize(swirl);
    return l;
  };
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  EXPECT_LT(max_relative_difference(make, GetParam()), kTolerance);
  omp_set_num_threads(threads);
}

// Even and odd step counts end in the two layouts of the AA buffer.
INSTANTIATE_TEST_SUITE_P(EvenAndOdd, AaSteps, ::testing::Values(1L, 8L, 9L));

TEST(AaPattern, PlanePoiseuilleIsExactToRoundOff) {
  // As channel_test: TRT with Lambda = 3/16 makes half-way bounce-back exact for the parabola; 1e-10 of u_max.
  const int width = 8;
  const CollisionParams collision{.model = CollisionModel::trt, .tau = 2.0, .magic = trt_magic_default};
  FluidLattice lattice(LatticeSpec{.global_nodes = {2, width, 2}, .periodic = {true, false, true},
                                   .collision = collision, .ranks_per_axis = {}, .rho0_lu = 1.0,
                                   .streaming = Streaming::aa},
                       MPI_COMM_SELF);
  const double u_max = 0.01;
  const double nu = collision.viscosity_lu();
  const double g = 8.0 * nu * u_max / (width * width);
  lattice.set_body_force({g, 0.0, 0.0});
  lattice.initialize();
  test::run_to_steady_state(lattice, 1e-14, 200, 400000);
  for (int y = 0; y < width; ++y) {
    const double exact = g / (2.0 * nu) * (y + 0.5) * (width - 0.5 - y);
    EXPECT_LT(std::abs(lattice.moments(1, y, 1).u.x - exact) / u_max, 1e-10) << "y = " << y;
  }
}

TEST(AaPattern, OpenFacesAreRefused) {
  FluidLattice lattice(LatticeSpec{.global_nodes = {6, 4, 2}, .periodic = {false, false, true}, .collision = kTrt,
                                   .ranks_per_axis = {}, .rho0_lu = 1.0, .streaming = Streaming::aa},
                       MPI_COMM_SELF);
  lattice.set_pressure_outlet(0, 1, 1.0);
  EXPECT_THROW(lattice.initialize(), std::invalid_argument);
}

}  // namespace
}  // namespace hs::resolved
