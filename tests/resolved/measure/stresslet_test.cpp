// SPDX-License-Identifier: MIT
// The stresslet of a rigid sphere in shear, from the exact surface traction on a discrete sphere, gives Einstein's
// intrinsic viscosity 2.5.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "resolved/measure/stresslet.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hr = hs::resolved;
using hs::common::Vec3;

// A rigid sphere (a = 4 um) held in the simple shear u_x = gamma_dot y of plasma: the fluid's traction on it is
// t = -p_inf n + 5 mu E.n + (the rotation's part, zero for a sphere turning with the vorticity), E the strain
// rate (E_xy = E_yx = gamma_dot / 2). Integrated as a discrete sum over a 642-vertex icosphere with vertex areas
// (one third of the adjacent triangles), sum x (x) t A must give 20/3 pi mu a^3 E, i.e. [eta] = 2.5 (Einstein
// 1906). The discrete sum of n (x) n A over this mesh is within ~0.5% of 4 pi a^2 / 3 I, so 1% is asked.
TEST(Stresslet, ARigidSphereInShearGivesEinsteinsTwoAndAHalf) {
  const double a = 4e-6, mu = 1.2e-3, gamma_dot = 100.0, p_inf = 37.0;
  hr::TriangleMesh mesh = hr::make_sphere_mesh(642);
  for (auto& v : mesh.vertices_m) v = hs::common::normalized(v) * a;   // on the sphere exactly
  const auto area = hr::vertex_areas_m2(mesh);
  std::vector<Vec3> x, f;
  for (std::size_t k = 0; k < mesh.vertices_m.size(); ++k) {
    const Vec3 n = hs::common::normalized(mesh.vertices_m[k]);
    const Vec3 e_n{0.5 * gamma_dot * n.y, 0.5 * gamma_dot * n.x, 0.0};   // E . n
    x.push_back(mesh.vertices_m[k] + Vec3{1e-5, -2e-5, 3e-5});            // anywhere: the centroid is taken off
    f.push_back((-p_inf * n + 5.0 * mu * e_n) * area[k]);
  }
  const hr::Stresslet s = hr::stresslet(x, f);
  const double volume = 4.0 / 3.0 * M_PI * a * a * a;
  EXPECT_NEAR(hr::intrinsic_viscosity(s, mu, gamma_dot, volume, 0, 1), 2.5, 0.025);
  EXPECT_NEAR(s[0][1], s[1][0], 1e-30);   // symmetric
  // No normal-stress part in simple shear, and the ambient pressure adds nothing (traceless).
  const double scale = std::abs(s[0][1]);
  EXPECT_LT(std::abs(s[0][0]) / scale, 0.01);
  EXPECT_LT(std::abs(s[2][2]) / scale, 0.01);
}
