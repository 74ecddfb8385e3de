// SPDX-License-Identifier: MIT
// A closed triangle surface read from STL: welded vertices, checked to be a closed, consistently oriented
// 2-manifold before any solver sees it.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "common/vec3.hpp"

namespace hs::common {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;

  /// Signed volume by the divergence theorem: > 0 when normals point outward.
  [[nodiscard]] double signed_volume() const;
};

/// Reads binary or ASCII STL, scales coordinates by `scale_to_m` (e.g. 1e-6 for a file in micrometres) and
/// welds coincident vertices. Throws ConfigError naming the file on an unreadable or empty file.
TriangleMesh read_stl(const std::filesystem::path& file, double scale_to_m = 1.0);

/// Throws ConfigError naming `source` unless every edge is shared by exactly two triangles with opposite
/// orientation and no triangle is degenerate. Flips all triangles if the surface is oriented inward.
void require_closed_manifold(TriangleMesh& mesh, const std::string& source);

}  // namespace hs::common
