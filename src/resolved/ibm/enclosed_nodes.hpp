// SPDX-License-Identifier: MIT
// The lattice nodes a closed triangle mesh encloses: the inside/outside indicator of a cell's membrane.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/vec3.hpp"

namespace hs::resolved {

/// The lattice the nodes belong to: global nodes per axis and which axes are periodic.
struct NodeBox {
  std::array<int, 3> nodes{};
  std::array<bool, 3> periodic{};
};

/// Global coordinates of the lattice nodes inside the closed triangle mesh (`x_lu`: vertices in global lattice
/// coordinates, node (i, j, k) at (i, j, k); unwrapped, so a cell may straddle a periodic face), wrapped into the box
/// along periodic axes; nodes beyond a non-periodic face are left out. Each node is listed once.
///
/// Method: ray crossing along z (Lehmann, Mueller & Gekle 2020, Int J Numer Meth Fluids 92:1463, compare theirs with
/// ray casting; Postek, Kajanek & Ondrusova 2020, Proc. BIOINFORMATICS, detect lattice points inside an RBC mesh by ray
/// crossings). Every triangle is projected onto the (x, y) plane and, for each lattice column (i, j) its projection
/// covers, gives one crossing at height z with the sign of its projected orientation. A node's winding number is the
/// sum of the signs of the crossings above it: +-1 inside a closed mesh, 0 outside, whichever way it is oriented
/// (a ray leaving the body crosses one more outward-facing than inward-facing triangle). A column through an edge or
/// vertex is decided by symbolic perturbation: the point is moved by (e, e^2) with e -> 0, and each edge function is
/// evaluated with its end points in one fixed order (by vertex index), so the two triangles sharing an edge agree to
/// the last bit and the column is counted exactly once. Cost: O(triangles + columns covered + nodes inside).
/// pre: the mesh is closed (every edge shared by two triangles, in opposite directions) and has no self-intersection.
[[nodiscard]] std::vector<std::array<int, 3>> enclosed_nodes(std::span<const common::Vec3> x_lu,
                                                            std::span<const std::array<int, 3>> triangles,
                                                            const NodeBox& box);

}  // namespace hs::resolved
