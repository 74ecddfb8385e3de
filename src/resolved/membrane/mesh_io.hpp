// SPDX-License-Identifier: MIT
// Reading and writing membrane meshes: Wavefront .obj (read/write) and VTK .vtp (write, for ParaView).
#pragma once

#include <filesystem>

#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

/// Writes "v x y z" lines in metres and "f i j k" (1-based) triangles.
void write_mesh_obj(const TriangleMesh& mesh, const std::filesystem::path& file);
/// Reads an .obj: `v` and `f` records (polygons with more than 3 corners, texture/normal indices and
/// negative indices are handled; other records ignored). Coordinates are multiplied by `length_unit_m`
/// (1 for metres, 1e-6 for micrometres). Throws ConfigError for an unreadable or malformed file.
/// The mesh is not validated: call validate_mesh().
[[nodiscard]] TriangleMesh read_mesh_obj(const std::filesystem::path& file, double length_unit_m = 1.0);
/// Writes the mesh (metres) with vertex normals and vertex areas as point data.
void write_mesh_vtp(const TriangleMesh& mesh, const std::filesystem::path& file);

}  // namespace hs::resolved
