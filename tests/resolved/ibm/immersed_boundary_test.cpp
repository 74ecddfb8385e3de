// SPDX-License-Identifier: MIT
// Immersed boundary: force conservation of spreading (also across periodic faces and at walls), exact interpolation
// of a uniform state, and the slip reduction of multi-direct forcing with the number of iterations.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <random>

#include "ibm_test_helpers.hpp"
#include "resolved/ibm/immersed_boundary.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

std::unique_ptr<FluidLattice> periodic_box(int n, const Vec3& u0) {
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {n, n, n}, .periodic = {true, true, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = 1.0}},
      MPI_COMM_WORLD);
  lattice->enable_force_field();
  lattice->initialize([&](const Vec3&) { return NodeInit{.rho_lu = 1.0, .u_lu = u0}; });
  return lattice;
}

Vec3 summed_force_field(FluidLattice& lattice) {
  const auto& n = lattice.layout().n;
  Vec3 sum;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) sum += lattice.force(x, y, z);
  double s[3] = {sum.x, sum.y, sum.z};
  MPI_Allreduce(MPI_IN_PLACE, s, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return {s[0], s[1], s[2]};
}

class IbmKernels : public ::testing::TestWithParam<int> {};

TEST_P(IbmKernels, SpreadingConservesTotalForceAcrossPeriodicFaces) {
  auto lattice = periodic_box(12, {});
  ImmersedBoundary ibm(*lattice, {.kernel = delta_kernel_from_points(GetParam()), .iterations = 1, .measure_slip = false});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-14.0, 26.0);   // markers inside, near and far outside the box
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::vector<Vec3> x, f;
  Vec3 total;
  for (int k = 0; k < 50; ++k) {
    x.push_back({pos(rng), pos(rng), pos(rng)});
    f.push_back({val(rng), val(rng), val(rng)});
    total += f.back();
  }
  x.push_back({-0.3, 11.8, 5.5});   // a stencil split by the periodic faces
  f.push_back({2.0, -1.0, 0.5});
  total += f.back();
  ibm.spread(x, f);
  const Vec3 spread = summed_force_field(*lattice);
  // Weights sum to one to round-off; 51 forces of O(1) summed over ~3000 terms: 1e-12 leaves ample margin.
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(spread[a], total[a], 1e-12) << "axis " << a;
}

TEST_P(IbmKernels, InterpolatesUniformStateExactlyAndPeriodicImagesAgree) {
  const Vec3 u0{0.02, -0.01, 0.005};
  auto lattice = periodic_box(12, u0);
  ImmersedBoundary ibm(*lattice, {.kernel = delta_kernel_from_points(GetParam()), .iterations = 1, .measure_slip = false});
  const std::vector<Vec3> x{{3.3, 4.7, 5.1}, {-0.4, 11.6, 0.2}, {11.6, -0.4, 12.2}};
  const MarkerFluid fluid = ibm.interpolate(x);
  for (std::size_t k = 0; k < x.size(); ++k) {
    EXPECT_NEAR(fluid.rho_lu[k], 1.0, 1e-13);   // round-off of the weight sum
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(fluid.u_lu[k][a], u0[a], 1e-14);
  }
}

/// A periodic box of n^3 nodes with walls at the two y faces, at rest at density rho (an exact steady state: the
/// walls' bounced populations equal the incoming ones).
std::unique_ptr<FluidLattice> walled_box_at_rest(int n, double rho) {
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {n, n, n}, .periodic = {true, false, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = 1.0}},
      MPI_COMM_WORLD);
  lattice->enable_force_field();
  lattice->initialize([&](const Vec3&) { return NodeInit{.rho_lu = rho, .u_lu = {}}; });
  return lattice;
}

TEST_P(IbmKernels, StencilsCutByAWallStillConserveForceAndInterpolateExactly) {
  auto lattice = walled_box_at_rest(12, 1.2);
  ImmersedBoundary ibm(*lattice, {.kernel = delta_kernel_from_points(GetParam()), .iterations = 1, .measure_slip = false});
  // Markers 0.2 and 0.7 lu inside the first and last node layers: every stencil reaches beyond a wall.
  const std::vector<Vec3> x{{3.3, 0.2, 5.1}, {7.6, 10.7, 2.4}, {0.4, 0.7, 11.5}};
  const std::vector<Vec3> f{{1.0, -0.5, 0.25}, {-2.0, 0.3, 1.0}, {0.5, 0.5, 0.5}};
  const MarkerFluid fluid = ibm.interpolate(x);   // before spreading: the half-force velocity would include it
  for (std::size_t k = 0; k < x.size(); ++k) {
    // The fluid's density, not a blend with the walls' (before: rho0 = 1 counted for the wall nodes).
    EXPECT_NEAR(fluid.rho_lu[k], 1.2, 1e-13);   // round-off of the renormalised weight sum
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(fluid.u_lu[k][a], 0.0, 1e-15);
  }
  ibm.spread(x, f);
  const Vec3 spread = summed_force_field(*lattice);
  const Vec3 total = f[0] + f[1] + f[2];
  // The fluid nodes' weights are renormalised to one: round-off of ~50 terms (before: 10-40 % went into the walls).
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(spread[a], total[a], 1e-13) << "axis " << a;
}

INSTANTIATE_TEST_SUITE_P(Points, IbmKernels, ::testing::Values(2, 3, 4));

/// Max slip after multi-direct forcing on a sphere at rest in a uniform stream.
double slip_after(int iterations, double* before = nullptr) {
  const Vec3 u0{0.03, 0.0, 0.0};
  auto lattice = periodic_box(20, u0);
  ImmersedBoundary ibm(*lattice, {.kernel = DeltaKernel::four_point, .iterations = iterations, .measure_slip = true});
  const ForcingReport report = ibm.apply(sphere_markers({9.6, 10.1, 9.9}, 4.0, 200));
  if (before != nullptr) *before = report.slip_before_lu;
  return report.slip_after_lu;
}

TEST(MultiDirectForcing, SlipDropsWithIterations) {
  double before = 0.0;
  const double s1 = slip_after(1, &before);
  const double s3 = slip_after(3);
  const double s8 = slip_after(8);
  std::printf("[ibm] max slip / u0: before %.4f, 1 it %.4f, 3 it %.4f, 8 it %.4f\n", before / 0.03, s1 / 0.03,
              s3 / 0.03, s8 / 0.03);
  EXPECT_NEAR(before, 0.03, 1e-14);   // uniform stream, nothing spread yet
  EXPECT_LT(s1, before);
  EXPECT_LT(s3, s1);
  EXPECT_LT(s8, s3);
  // Multi-direct forcing is a fixed-point iteration whose error contracts geometrically (Wang, Fan & Luo 2008):
  // 8 iterations must remove at least 90% of the initial slip, otherwise the iteration is not converging.
  EXPECT_LT(s8, 0.1 * before);
}

}  // namespace
}  // namespace hs::resolved
