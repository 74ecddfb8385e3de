// SPDX-License-Identifier: MIT
// Geometric measures of a triangulated surface: edges, area, volume, vertex areas and normals.
#include "resolved/membrane/triangle_mesh.hpp"

#include <algorithm>

namespace hs::resolved {

using hs::common::Vec3;

std::vector<std::array<int, 2>> mesh_edges(const TriangleMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k];
      const int b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

double mesh_area_m2(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices_m[t[0]];
    area += 0.5 * norm(cross(mesh.vertices_m[t[1]] - a, mesh.vertices_m[t[2]] - a));
  }
  return area;
}

double mesh_volume_m3(const TriangleMesh& mesh) {
  const Vec3 c = mesh_centroid_m(mesh);   // reference point near the body keeps round-off small
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    volume += dot(mesh.vertices_m[t[0]] - c, cross(mesh.vertices_m[t[1]] - c, mesh.vertices_m[t[2]] - c));
  }
  return volume / 6.0;
}

std::vector<double> vertex_areas_m2(const TriangleMesh& mesh) {
  std::vector<double> areas(mesh.vertices_m.size(), 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices_m[t[0]];
    const double third = norm(cross(mesh.vertices_m[t[1]] - a, mesh.vertices_m[t[2]] - a)) / 6.0;
    for (int k = 0; k < 3; ++k) areas[t[k]] += third;
  }
  return areas;
}

std::vector<Vec3> vertex_normals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices_m.size());
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices_m[t[0]];
    const Vec3 n2 = cross(mesh.vertices_m[t[1]] - a, mesh.vertices_m[t[2]] - a);   // |n2| = 2 A
    for (int k = 0; k < 3; ++k) normals[t[k]] += n2;
  }
  for (auto& n : normals) {
    const double len = norm(n);
    if (len > 0.0) n = n / len;
  }
  return normals;
}

Vec3 mesh_centroid_m(const TriangleMesh& mesh) {
  Vec3 c;
  for (const auto& v : mesh.vertices_m) c += v;
  return mesh.vertices_m.empty() ? c : c / static_cast<double>(mesh.vertices_m.size());
}

}  // namespace hs::resolved
