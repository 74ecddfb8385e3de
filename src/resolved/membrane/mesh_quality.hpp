// SPDX-License-Identifier: MIT
// Mesh quality report (edges, angles, area, volume, normals, topology) and validation of input meshes.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

struct MeshQuality {
  int vertices = 0;
  int triangles = 0;
  int edges = 0;
  int euler_characteristic = 0;        // V - E + F: 2 for a closed sphere-like surface
  double edge_min_m = 0.0;
  double edge_max_m = 0.0;
  double edge_mean_m = 0.0;
  double angle_min_deg = 0.0;
  double angle_max_deg = 0.0;
  double area_m2 = 0.0;
  double volume_m3 = 0.0;
  double normal_closure = 0.0;          // |sum_v A_v n_v| / sum_v A_v: 0 for a closed surface
  double outward_normal_fraction = 0.0; // share of vertices with n_v . (x_v - centroid) > 0
  double triangle_area_ratio = 0.0;     // largest / smallest triangle area
};

/// Measures a mesh (any mesh; see validate_mesh for the checks).
[[nodiscard]] MeshQuality mesh_quality(const TriangleMesh& mesh);
/// The report as JSON (SI units, keys carry the unit).
[[nodiscard]] nlohmann::json to_json(const MeshQuality& q);

/// Checks that `mesh` is a usable cell surface: indices in range, no degenerate triangle, every edge shared by
/// exactly two triangles with opposite orientations (closed, manifold, consistently oriented), Euler
/// characteristic 2, positive enclosed volume (normals outward). Throws ConfigError naming `source` and the
/// first offending element.
void validate_mesh(const TriangleMesh& mesh, const std::string& source);

}  // namespace hs::resolved
