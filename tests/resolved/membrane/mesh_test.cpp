// SPDX-License-Identifier: MIT
// The biconcave RBC mesh: Evans–Fung area and volume, topology, outward normals, relaxation and file round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "resolved/membrane/evans_fung_shape.hpp"
#include "resolved/membrane/mesh_io.hpp"
#include "resolved/membrane/mesh_quality.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

using namespace hs::resolved;

namespace {
// Exact Evans–Fung surface at D0 = 7.82 um (reference/validation/README.md): 134.1 um^2, 94.1 um^3.
constexpr double exact_area_m2 = 134.1e-12;
constexpr double exact_volume_m3 = 94.1e-18;
}  // namespace

TEST(RbcMesh, Default258VerticesMatchesEvansFungWithin3Percent) {
  const MeshQuality q = mesh_quality(make_rbc_mesh({}));
  EXPECT_EQ(q.vertices, 258);
  EXPECT_EQ(q.triangles, 512);
  EXPECT_EQ(q.euler_characteristic, 2);
  // 3%: the acceptance band; an inscribed polyhedron of 258 vertices underestimates both measures.
  EXPECT_NEAR(q.area_m2 / exact_area_m2, 1.0, 0.03);
  EXPECT_NEAR(q.volume_m3 / exact_volume_m3, 1.0, 0.03);
  EXPECT_DOUBLE_EQ(q.outward_normal_fraction, 1.0);
  EXPECT_LT(q.normal_closure, 1e-12);   // sum A_v n_v = 0 holds to round-off for any closed mesh
  EXPECT_GT(q.volume_m3, 0.0);
  EXPECT_NO_THROW(validate_mesh(make_rbc_mesh({}), "258"));
}

TEST(RbcMesh, AllResolutionsAreClosedSpheresThatConvergeToTheExactShape) {
  double previous_error = 1.0;
  for (const int n : {66, 258, 1026}) {
    const MeshQuality q = mesh_quality(make_rbc_mesh({.vertex_count = n}));
    EXPECT_EQ(q.euler_characteristic, 2) << n;
    const double error = std::abs(q.volume_m3 / exact_volume_m3 - 1.0);
    EXPECT_LT(error, previous_error) << n;   // refinement must approach the exact surface
    previous_error = error;
  }
  for (const int n : {162, 642, 2562}) {
    const TriangleMesh m = make_rbc_mesh({.vertex_count = n});
    EXPECT_NO_THROW(validate_mesh(m, "icosphere")) << n;
    const MeshQuality q = mesh_quality(m);
    EXPECT_EQ(q.vertices, n);
    EXPECT_DOUBLE_EQ(q.outward_normal_fraction, 1.0);
  }
  // 642 vertices: within 1.5% of the exact measures (finer than 258; measured 0.6% (area) and 0.9% (volume)).
  const MeshQuality q642 = mesh_quality(make_rbc_mesh({.vertex_count = 642}));
  EXPECT_NEAR(q642.volume_m3 / exact_volume_m3, 1.0, 0.015);
  EXPECT_NEAR(q642.area_m2 / exact_area_m2, 1.0, 0.015);
}

TEST(RbcMesh, VerticesLieOnTheEvansFungSurface) {
  const EvansFungShape shape;
  for (const int relax : {0, 20}) {
    for (const auto& v : make_rbc_mesh({.relax_iterations = relax}).vertices_m) {
      EXPECT_NEAR(shape.implicit(v), 0.0, 1e-12) << relax;   // Newton projection converges to round-off
    }
  }
  EXPECT_NEAR(2.0 * shape.half_thickness_m(0.0), 0.81e-6, 0.01e-6);   // centre thickness 0.81 um (Evans & Fung)
}

TEST(RbcMesh, RelaxationImprovesTriangleShapes) {
  for (const int n : {258, 642}) {
    const MeshQuality plain = mesh_quality(make_rbc_mesh({.vertex_count = n}));
    const MeshQuality relaxed = mesh_quality(make_rbc_mesh({.vertex_count = n, .relax_iterations = 20}));
    EXPECT_GT(relaxed.angle_min_deg, plain.angle_min_deg + 5.0) << n;   // measured 29 -> 38 deg (258), 37 -> 43 (642)
    EXPECT_LT(relaxed.edge_max_m / relaxed.edge_min_m, plain.edge_max_m / plain.edge_min_m) << n;
    EXPECT_EQ(relaxed.euler_characteristic, 2);
    // Relaxation moves vertices off the thick rim a little: measured -3.15% volume at 258 (plain mesh -2.4%),
    // which is why it is off by default; 3.5% bounds that.
    EXPECT_NEAR(relaxed.volume_m3 / exact_volume_m3, 1.0, 0.035);
  }
  // On the icosphere mesh the relaxation also evens out triangle areas (measured ratio 2.14 -> 1.64).
  EXPECT_LT(mesh_quality(make_rbc_mesh({.vertex_count = 642, .relax_iterations = 20})).triangle_area_ratio,
            mesh_quality(make_rbc_mesh({.vertex_count = 642})).triangle_area_ratio);
}

TEST(RbcMesh, ObjRoundTripIsExactAndVtpIsWritten) {
  const TriangleMesh m = make_rbc_mesh({.vertex_count = 162});
  const auto dir = std::filesystem::temp_directory_path() / "hs_membrane_mesh_test";
  std::filesystem::create_directories(dir);
  write_mesh_obj(m, dir / "rbc.obj");
  const TriangleMesh back = read_mesh_obj(dir / "rbc.obj");
  ASSERT_EQ(back.vertex_count(), m.vertex_count());
  ASSERT_EQ(back.triangles, m.triangles);
  for (int i = 0; i < m.vertex_count(); ++i) EXPECT_EQ(back.vertices_m[i].x, m.vertices_m[i].x);   // 17 digits
  write_mesh_vtp(m, dir / "rbc.vtp");
  EXPECT_GT(std::filesystem::file_size(dir / "rbc.vtp"), 1000u);
  std::filesystem::remove_all(dir);
}
