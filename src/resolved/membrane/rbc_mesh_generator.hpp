// SPDX-License-Identifier: MIT
// Builds the biconcave RBC mesh at any resolution from a subdivided octahedron or icosahedron.
#pragma once

#include <optional>

#include "resolved/membrane/evans_fung_shape.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

struct RbcMeshOptions {
  /// 4*4^k + 2 (octahedron: 66, 258, 1026, 4098) or 10*4^k + 2 (icosahedron: 162, 642, 2562).
  /// 258 is the mesh of Kotsalos et al. 2019 and of the seed paper (reference §4.2).
  int vertex_count = 258;
  double diameter_m = EvansFungShape::default_diameter_m;
  /// Area-equalising relaxation sweeps on the biconcave surface (0 = plain (x, y)-scaling map).
  int relax_iterations = 0;
  /// The spectrin network's stress-free shape: empty = the biconcave rest shape itself (full shape memory); a value =
  /// an oblate spheroid of this reduced volume, mapped area for area (resolved/membrane/stress_free_shape.hpp).
  std::optional<double> stress_free_reduced_volume = std::nullopt;
};

/// Sphere points of the subdivided polyhedron, mapped with X = R0 x, Y = R0 y, Z = sign(z) z_EF(r)
/// (reference §4.2), then optionally relaxed tangentially towards equal triangle areas and re-projected
/// on the surface; with its oblate stress-free shape when the options ask for one. Triangles are oriented outward.
/// Throws ConfigError for an unsupported vertex count.
[[nodiscard]] TriangleMesh make_rbc_mesh(const RbcMeshOptions& options);

/// The unit sphere mesh before mapping (used by the generator and by tests of the bending energy).
[[nodiscard]] TriangleMesh make_sphere_mesh(int vertex_count);

/// True when `vertex_count` is one the generator can build.
[[nodiscard]] bool is_supported_vertex_count(int vertex_count);

}  // namespace hs::resolved
