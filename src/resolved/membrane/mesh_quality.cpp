// SPDX-License-Identifier: MIT
// Mesh quality measures and the closed/manifold/oriented checks for input meshes.
#include "resolved/membrane/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::resolved {
namespace {

using hs::common::ConfigError;
using hs::common::Vec3;

double angle_deg(const Vec3& at, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - at;
  const Vec3 v = c - at;
  return std::atan2(norm(cross(u, v)), dot(u, v)) * 180.0 / std::numbers::pi;
}

}  // namespace

MeshQuality mesh_quality(const TriangleMesh& mesh) {
  MeshQuality q;
  const auto edges = mesh_edges(mesh);
  q.vertices = mesh.vertex_count();
  q.triangles = mesh.triangle_count();
  q.edges = static_cast<int>(edges.size());
  q.euler_characteristic = q.vertices - q.edges + q.triangles;
  q.edge_min_m = std::numeric_limits<double>::max();
  for (const auto& e : edges) {
    const double len = norm(mesh.vertices_m[e[1]] - mesh.vertices_m[e[0]]);
    q.edge_min_m = std::min(q.edge_min_m, len);
    q.edge_max_m = std::max(q.edge_max_m, len);
    q.edge_mean_m += len / static_cast<double>(edges.size());
  }
  q.angle_min_deg = 180.0;
  double area_min = std::numeric_limits<double>::max();
  double area_max = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices_m[t[0]];
    const Vec3& b = mesh.vertices_m[t[1]];
    const Vec3& c = mesh.vertices_m[t[2]];
    for (const double ang : {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)}) {
      q.angle_min_deg = std::min(q.angle_min_deg, ang);
      q.angle_max_deg = std::max(q.angle_max_deg, ang);
    }
    const double area = 0.5 * norm(cross(b - a, c - a));
    area_min = std::min(area_min, area);
    area_max = std::max(area_max, area);
  }
  q.triangle_area_ratio = area_min > 0.0 ? area_max / area_min : std::numeric_limits<double>::infinity();
  q.area_m2 = mesh_area_m2(mesh);
  q.volume_m3 = mesh_volume_m3(mesh);
  const auto areas = vertex_areas_m2(mesh);
  const auto normals = vertex_normals(mesh);
  const Vec3 centroid = mesh_centroid_m(mesh);
  Vec3 closure;
  int outward = 0;
  for (int v = 0; v < q.vertices; ++v) {
    closure += normals[v] * areas[v];
    if (dot(normals[v], mesh.vertices_m[v] - centroid) > 0.0) ++outward;
  }
  q.normal_closure = norm(closure) / q.area_m2;
  q.outward_normal_fraction = static_cast<double>(outward) / std::max(1, q.vertices);
  return q;
}

nlohmann::json to_json(const MeshQuality& q) {
  return {{"vertices", q.vertices}, {"triangles", q.triangles}, {"edges", q.edges},
          {"euler_characteristic", q.euler_characteristic}, {"edge_min_m", q.edge_min_m},
          {"edge_max_m", q.edge_max_m}, {"edge_mean_m", q.edge_mean_m}, {"angle_min_deg", q.angle_min_deg},
          {"angle_max_deg", q.angle_max_deg}, {"area_m2", q.area_m2}, {"volume_m3", q.volume_m3},
          {"normal_closure", q.normal_closure}, {"outward_normal_fraction", q.outward_normal_fraction},
          {"triangle_area_ratio", q.triangle_area_ratio}};
}

void validate_mesh(const TriangleMesh& mesh, const std::string& source) {
  const int n = mesh.vertex_count();
  if (n < 4 || mesh.triangle_count() < 4) {
    throw ConfigError(fmt::format("{}: mesh has {} vertices and {} triangles; a closed cell surface needs at least 4 of each",
                                  source, n, mesh.triangle_count()));
  }
  std::map<std::pair<int, int>, int> directed;   // directed edge -> number of triangles using it
  for (int i = 0; i < mesh.triangle_count(); ++i) {
    const auto& t = mesh.triangles[i];
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= n) {
        throw ConfigError(fmt::format("{}: triangle {} refers to vertex {}, but the mesh has {} vertices (0-based)",
                                      source, i, t[k], n));
      }
    }
    const Vec3& a = mesh.vertices_m[t[0]];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
        norm(cross(mesh.vertices_m[t[1]] - a, mesh.vertices_m[t[2]] - a)) <= 0.0) {
      throw ConfigError(fmt::format("{}: triangle {} ({}, {}, {}) is degenerate (zero area)", source, i, t[0], t[1], t[2]));
    }
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto twin = directed.find({edge.second, edge.first});
    const int opposite = twin == directed.end() ? 0 : twin->second;
    if (count == 1 && opposite == 0) {
      throw ConfigError(fmt::format("{}: open surface: edge ({}, {}) belongs to only one triangle; the membrane mesh "
                                    "must be closed", source, edge.first, edge.second));
    }
    if (count + opposite > 2) {
      throw ConfigError(fmt::format("{}: non-manifold edge ({}, {}) is shared by {} triangles; each edge must join "
                                    "exactly two", source, edge.first, edge.second, count + opposite));
    }
    if (count != 1 || opposite != 1) {
      throw ConfigError(fmt::format("{}: inverted triangle: edge ({}, {}) runs the same way in both of its triangles; "
                                    "all triangles must be ordered counter-clockwise seen from outside",
                                    source, edge.first, edge.second));
    }
  }
  const int euler = n - static_cast<int>(directed.size() / 2) + mesh.triangle_count();
  if (euler != 2) {
    throw ConfigError(fmt::format("{}: Euler characteristic V - E + F = {} (must be 2: one closed surface of sphere "
                                  "topology, no holes or handles, no unused vertices)", source, euler));
  }
  if (mesh_volume_m3(mesh) <= 0.0) {
    throw ConfigError(fmt::format("{}: inverted mesh: enclosed volume {:.4g} m^3 is not positive, so the normals point "
                                  "inward; reverse the vertex order of every triangle", source, mesh_volume_m3(mesh)));
  }
}

}  // namespace hs::resolved
