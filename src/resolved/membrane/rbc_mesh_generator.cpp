// SPDX-License-Identifier: MIT
// Subdivided octahedron / icosahedron spheres mapped onto the Evans–Fung shape, with optional relaxation.
#include "resolved/membrane/rbc_mesh_generator.hpp"

#include <cmath>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "resolved/membrane/stress_free_shape.hpp"

namespace hs::resolved {
namespace {

using hs::common::Vec3;

TriangleMesh octahedron() {
  TriangleMesh m;
  m.vertices_m = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

/// Regular icosahedron rotated about x so that one vertex sits on the +z pole (and one on -z).
TriangleMesh icosahedron() {
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  TriangleMesh m;
  m.vertices_m = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
                  {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  const double theta = std::atan2(1.0, phi);   // brings (0, 1, phi) onto the z axis
  for (auto& v : m.vertices_m) {
    v = normalized(Vec3{v.x, v.y * std::cos(theta) - v.z * std::sin(theta), v.y * std::sin(theta) + v.z * std::cos(theta)});
  }
  return m;
}

/// One midpoint subdivision: every triangle becomes four; new points are pushed onto the unit sphere.
TriangleMesh subdivide(const TriangleMesh& in) {
  TriangleMesh out;
  out.vertices_m = in.vertices_m;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    out.vertices_m.push_back(normalized(out.vertices_m[a] + out.vertices_m[b]));
    const int id = static_cast<int>(out.vertices_m.size()) - 1;
    midpoint.emplace(key, id);
    return id;
  };
  for (const auto& t : in.triangles) {
    const int ab = mid(t[0], t[1]);
    const int bc = mid(t[1], t[2]);
    const int ca = mid(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({t[1], bc, ab});
    out.triangles.push_back({t[2], ca, bc});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

/// Makes every triangle of a star-shaped (about the origin) mesh face away from the origin.
void orient_outward(TriangleMesh& m) {
  for (auto& t : m.triangles) {
    const Vec3& a = m.vertices_m[t[0]];
    const Vec3 n = cross(m.vertices_m[t[1]] - a, m.vertices_m[t[2]] - a);
    if (dot(n, a + m.vertices_m[t[1]] + m.vertices_m[t[2]]) < 0.0) std::swap(t[1], t[2]);
  }
}

/// One sweep: each vertex moves half-way (tangentially) towards the average of its edge neighbours, weighted by
/// the areas of the two triangles beside each edge (pulls vertices towards large triangles, shrinking them).
void relax_sweep(TriangleMesh& m, const EvansFungShape& shape) {
  std::vector<Vec3> target(m.vertices_m.size());
  std::vector<double> weight(m.vertices_m.size(), 0.0);
  for (const auto& t : m.triangles) {
    const Vec3& a = m.vertices_m[t[0]];
    const double area = 0.5 * norm(cross(m.vertices_m[t[1]] - a, m.vertices_m[t[2]] - a));
    for (int k = 0; k < 3; ++k) {
      for (const int other : {t[(k + 1) % 3], t[(k + 2) % 3]}) {
        target[t[k]] += m.vertices_m[other] * area;
        weight[t[k]] += area;
      }
    }
  }
  const auto normals = vertex_normals(m);
  for (std::size_t v = 0; v < m.vertices_m.size(); ++v) {
    Vec3 d = target[v] / weight[v] - m.vertices_m[v];
    d -= normals[v] * dot(d, normals[v]);
    m.vertices_m[v] = shape.project(m.vertices_m[v] + 0.5 * d);
  }
}

}  // namespace

bool is_supported_vertex_count(int vertex_count) {
  for (int n = 6; n <= 70000; n = 4 * (n - 2) + 2) {
    if (n == vertex_count && n >= 18) return true;
  }
  for (int n = 12; n <= 70000; n = 4 * (n - 2) + 2) {
    if (n == vertex_count && n >= 42) return true;
  }
  return false;
}

TriangleMesh make_sphere_mesh(int vertex_count) {
  if (!is_supported_vertex_count(vertex_count)) {
    throw hs::common::ConfigError(fmt::format(
        "RBC mesh vertices = {} is not supported: use 4*4^k+2 (octahedron: 66, 258, 1026) or "
        "10*4^k+2 (icosahedron: 162, 642, 2562)", vertex_count));
  }
  const bool octa = (vertex_count - 2) % 10 != 0;   // n-2 is 4^(k+1) (no factor 5) or 10*4^k
  TriangleMesh m = octa ? octahedron() : icosahedron();
  while (m.vertex_count() < vertex_count) m = subdivide(m);
  orient_outward(m);
  return m;
}

TriangleMesh make_rbc_mesh(const RbcMeshOptions& options) {
  const EvansFungShape shape(options.diameter_m);
  TriangleMesh m = make_sphere_mesh(options.vertex_count);
  const double r0 = 0.5 * options.diameter_m;
  for (auto& v : m.vertices_m) {
    const double r = r0 * std::sqrt(v.x * v.x + v.y * v.y);
    const double z = shape.half_thickness_m(r);
    v = Vec3{r0 * v.x, r0 * v.y, v.z > 0.0 ? z : (v.z < 0.0 ? -z : 0.0)};
  }
  for (int it = 0; it < options.relax_iterations; ++it) relax_sweep(m, shape);
  if (options.stress_free_reduced_volume) {
    m.stress_free_vertices_m = oblate_stress_free_vertices(m, shape, *options.stress_free_reduced_volume);
  }
  return m;
}

}  // namespace hs::resolved
