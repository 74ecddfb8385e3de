// SPDX-License-Identifier: MIT
// The ellipsoid with the same volume and second moment of volume as a closed membrane: the shape measure of the capsule
// literature (Ramanujan & Pozrikidis 1998), set by the enclosed volume rather than by where the vertices sit.
#pragma once

#include <array>
#include <span>

#include "common/vec3.hpp"

namespace hs::resolved {

struct EquivalentEllipsoid {
  common::Vec3 centroid_m;                   // centroid of the enclosed volume
  std::array<common::Vec3, 3> axes;          // unit principal axes, longest first
  std::array<double, 3> semi_axes_m{};       // a_i = sqrt(5 J_i / V), J_i the principal second moments; descending
  double volume_m3 = 0.0;

  /// Taylor's deformation D = (a1 - a2) / (a1 + a2) of the two principal axes nearest the plane normal to
  /// `vorticity` (the shear plane): the axis most aligned with the vorticity is left out.
  [[nodiscard]] double shear_plane_taylor_deformation(const common::Vec3& vorticity) const;
};

/// The equivalent ellipsoid of the closed, outward-oriented triangle surface (vertices, triangles): exact moments of
/// the polyhedron, summed over the tetrahedra its triangles span with an inner point.
/// pre: a closed surface enclosing positive volume.
EquivalentEllipsoid equivalent_ellipsoid(std::span<const common::Vec3> vertices_m,
                                         std::span<const std::array<int, 3>> triangles);

}  // namespace hs::resolved
