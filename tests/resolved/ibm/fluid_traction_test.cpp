// SPDX-License-Identifier: MIT
// Membrane traction from the fluid stress: exact viscous traction in Couette flow (small and large tau), mean
// pressure removal, the volume the sampling surface encloses, and the 1-ring median filter.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

#include "../lbm/lbm_test_helpers.hpp"
#include "resolved/ibm/fluid_traction.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

class CouetteTraction : public ::testing::TestWithParam<double> {};

TEST_P(CouetteTraction, ViscousTractionMatchesMuTimesShearRate) {
  const int height = 16;   // half-way walls at y = -1/2 and y = 15.5: gap H = 16
  const double u_wall = 0.02;
  const CollisionParams collision{.model = CollisionModel::trt, .tau = GetParam()};
  auto lattice = test::make_channel(height, collision, MPI_COMM_WORLD);
  lattice->set_face_wall_velocity(1, 1, {u_wall, 0.0, 0.0});
  lattice->initialize();
  test::run_to_steady_state(*lattice, 1e-13, 200, 200000);
  ImmersedBoundary ibm(*lattice, {});
  // Two membrane patches facing up (fluid above is faster: dragged forward) and down (dragged back).
  const std::vector<Vec3> x{{0.4, 7.3, 1.2}, {1.1, 8.6, 0.7}};
  const std::vector<Vec3> n{{0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}};
  const std::vector<double> area{1.3, 0.7};
  const TractionResult t = fluid_traction(ibm, *lattice, {x, n, area, {}}, {}, TractionArea::membrane);
  const double tau_xy = collision.viscosity_lu() * u_wall / height;   // mu gamma, rho = 1
  // Couette flow is exact on the lattice with half-way bounce-back and TRT; 1e-9 covers the steady-state residual.
  EXPECT_NEAR(t.force_lu[0].x, area[0] * tau_xy, 1e-9 * tau_xy);
  EXPECT_NEAR(t.force_lu[1].x, -area[1] * tau_xy, 1e-9 * tau_xy);
  for (int v = 0; v < 2; ++v) {
    EXPECT_NEAR(t.force_lu[static_cast<std::size_t>(v)].y, 0.0, 1e-9 * tau_xy);   // uniform pressure, mean removed
    EXPECT_NEAR(t.force_lu[static_cast<std::size_t>(v)].z, 0.0, 1e-12);
  }
  EXPECT_EQ(t.vertices_without_fluid, 0);
  EXPECT_NEAR(t.mean_pressure_lu, 1.0 / 3.0, 1e-6);   // rho stays 1 up to O(Ma^2) in Couette flow
}

INSTANTIATE_TEST_SUITE_P(Tau, CouetteTraction, ::testing::Values(0.8, 20.0));

TEST(OffsetAreaVectors, ScaleASphereByTheSquareOfItsRadiusAndCloseToZero) {
  // Moving the vertices of a unit-sphere mesh out along their radii by d scales the mesh by 1 + d exactly, so the
  // total area scales by (1 + d)^2 to round-off; a closed mesh's area vectors sum to zero to round-off.
  const TriangleMesh mesh = make_sphere_mesh(642);
  const std::vector<Vec3>& x = mesh.vertices_m;
  const double d = 0.75;
  const std::vector<double> zero(x.size(), 0.0);
  const std::vector<double> offset(x.size(), d);
  const auto a0 = offset_area_vectors(x, x, zero, mesh.triangles);
  const auto a1 = offset_area_vectors(x, x, offset, mesh.triangles);
  double total0 = 0.0;
  double total1 = 0.0;
  Vec3 sum;
  for (std::size_t v = 0; v < x.size(); ++v) {
    total0 += common::norm(a0[v]);
    total1 += common::norm(a1[v]);
    sum += a1[v];
    EXPECT_GT(common::dot(a1[v], x[v]), 0.0);   // outward
  }
  EXPECT_NEAR(total1 / total0, (1.0 + d) * (1.0 + d), 1e-12);
  EXPECT_LT(common::norm(sum), 1e-13 * total1);
}

TEST(EnclosedVolume, IsTheCellPlusTheShellOutToEachSampleNode) {
  // A sphere of radius R = 4 lu (642 vertices, radial normals) in fluid at rest. Offsetting along the radii scales
  // the mesh, so vertex v's parallel area at distance s is exactly |A_v| (1 + s / R)^2 and its shell out to its
  // sample distance d_v is |A_v| (d + d^2 / R + d^3 / (3 R^2)). The cones add up to the mesh volume, computed here
  // independently from the triangles.
  FluidLattice lattice(LatticeSpec{.global_nodes = {24, 24, 24}, .periodic = {true, true, true},
                                   .collision = CollisionParams{.model = CollisionModel::trt, .tau = 1.0}},
                       MPI_COMM_WORLD);
  lattice.initialize();
  ImmersedBoundary ibm(lattice, {});
  const TriangleMesh unit = make_sphere_mesh(642);
  const double radius = 4.0;
  const Vec3 centre{10.3, 10.6, 9.8};
  std::vector<Vec3> x;
  for (const auto& p : unit.vertices_m) x.push_back(centre + radius * p);
  const auto a0 = offset_area_vectors(x, unit.vertices_m, std::vector<double>(x.size(), 0.0), unit.triangles);
  std::vector<double> area;
  for (const auto& a : a0) area.push_back(common::norm(a));
  const TractionResult t = fluid_traction(ibm, lattice, {x, unit.vertices_m, area, unit.triangles}, {},
                                          TractionArea::scaled_membrane);
  double mesh_volume = 0.0;
  for (const auto& tri : unit.triangles) {
    const Vec3& p0 = x[static_cast<std::size_t>(tri[0])];
    mesh_volume += common::dot(p0 - centre, common::cross(x[static_cast<std::size_t>(tri[1])] - p0,
                                                          x[static_cast<std::size_t>(tri[2])] - p0)) / 6.0;
  }
  double expected = mesh_volume;
  double enclosed = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v) {
    const double d = t.sample_distance_lu[v];
    EXPECT_GE(d, 0.0);
    EXPECT_LE(d, 2.0 * std::sqrt(3.0));   // a 4-point stencil node is at most 2 lu from the marker along each axis
    expected += area[v] * (d + d * d / radius + d * d * d / (3.0 * radius * radius));
    enclosed += t.enclosed_volume_lu[v];
  }
  // Simpson's rule is exact for the quadratic parallel areas: round-off of ~600 terms.
  EXPECT_NEAR(enclosed, expected, 1e-10 * expected);
  EXPECT_GT(enclosed, 1.5 * mesh_volume);   // the shell is not small: 1-2 lu around a 4 lu sphere
}

TEST(MedianFilter, RemovesASpikeAndKeepsAUniformField) {
  // Octahedron: every vertex has 4 neighbours.
  const std::vector<std::array<int, 3>> tri{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                            {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const auto ring = one_ring(6, tri);
  ASSERT_EQ(ring[4].size(), 4u);
  std::vector<Vec3> f(6, Vec3{1.0, -2.0, 0.5});
  f[4] = {100.0, 50.0, -80.0};
  const auto g = median_filter(f, ring);
  for (const auto& v : g) {
    EXPECT_DOUBLE_EQ(v.x, 1.0);
    EXPECT_DOUBLE_EQ(v.y, -2.0);
    EXPECT_DOUBLE_EQ(v.z, 0.5);
  }
}

}  // namespace
}  // namespace hs::resolved
