// SPDX-License-Identifier: MIT
// A closed triangulated surface in metres, with the geometric measures the membrane and the coupling need.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"

namespace hs::resolved {

/// Vertices in metres; triangles list vertex indices counter-clockwise seen from outside (normal outward).
struct TriangleMesh {
  std::vector<hs::common::Vec3> vertices_m;
  std::vector<std::array<int, 3>> triangles;
  /// The membrane's in-plane stress-free shape, vertex by vertex (empty: the vertices themselves). Only lengths and
  /// angles within each triangle are read from it, so it need not follow the mesh when the mesh is moved or rotated.
  std::vector<hs::common::Vec3> stress_free_vertices_m = {};

  [[nodiscard]] int vertex_count() const { return static_cast<int>(vertices_m.size()); }
  [[nodiscard]] int triangle_count() const { return static_cast<int>(triangles.size()); }
};

/// Unique undirected edges (i < j), sorted.
[[nodiscard]] std::vector<std::array<int, 2>> mesh_edges(const TriangleMesh& mesh);
/// Total surface area in m^2.
[[nodiscard]] double mesh_area_m2(const TriangleMesh& mesh);
/// Enclosed volume in m^3 from the divergence theorem (positive for outward-oriented triangles).
[[nodiscard]] double mesh_volume_m3(const TriangleMesh& mesh);
/// Vertex area: one third of the areas of the adjacent triangles, m^2.
[[nodiscard]] std::vector<double> vertex_areas_m2(const TriangleMesh& mesh);
/// Unit outward vertex normals: area-weighted average of the adjacent triangle normals.
[[nodiscard]] std::vector<hs::common::Vec3> vertex_normals(const TriangleMesh& mesh);
/// Mean vertex position, m.
[[nodiscard]] hs::common::Vec3 mesh_centroid_m(const TriangleMesh& mesh);

}  // namespace hs::resolved
