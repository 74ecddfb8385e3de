// SPDX-License-Identifier: MIT
// The shape measures of a deformed cell from its membrane vertices: principal axes, deformation index
// DI = (L - B)/(L + B), projected lengths D_i = L_i / D0, and orientation.
#pragma once

#include <array>
#include <span>

#include "common/vec3.hpp"

namespace hs::resolved {

struct CellShape {
  common::Vec3 centroid_m;
  std::array<common::Vec3, 3> axes;          // unit principal axes, longest extent first
  std::array<double, 3> extents_m;           // vertex extent along each axis (max - min projection), descending
  std::array<double, 3> projected_m;         // extents along x, y, z (L_i for D_i = L_i / D0)
  std::array<double, 3> gyration_radii_m{};  // sqrt of the gyration tensor's eigenvalues / n (RMS spread), descending

  /// DI = (L - B)/(L + B) with L, B the longest and shortest principal extents (seed paper section 4).
  [[nodiscard]] double deformation_index() const {
    return (extents_m[0] - extents_m[2]) / (extents_m[0] + extents_m[2]);
  }
  /// The same index from the gyration radii: every vertex counts, where the extents are set by the two extreme vertices
  /// along each axis (a single vertex sticking out moves DI; issue #26's knob check). ~0.45 for the resting cell.
  [[nodiscard]] double gyration_deformation_index() const {
    return (gyration_radii_m[0] - gyration_radii_m[2]) / (gyration_radii_m[0] + gyration_radii_m[2]);
  }
};

/// Principal axes of the vertex cloud's second-moment (gyration) tensor; extents measured along them.
/// pre: at least 4 vertices, unwrapped across periodic boundaries.
CellShape measure_cell_shape(std::span<const common::Vec3> vertices_m);

/// Angle (rad, in (-pi/2, pi/2]) of the longest axis against `flow` within the plane spanned by `flow` and
/// `gradient` (the shear plane): the inclination angle of tank-treading and the tumbling angle.
double inclination_angle(const CellShape& shape, const common::Vec3& flow, const common::Vec3& gradient);

/// Angle (rad, in [0, pi/2]) between the shortest principal axis (a disc's normal) and `vorticity`: ~0 for a disc that
/// rolls (spins in the shear plane like a wheel), ~pi/2 for one that turns in the shear plane (tumbling, swinging,
/// tank-treading), between for an oblique (kayaking) motion.
double normal_to_vorticity_angle(const CellShape& shape, const common::Vec3& vorticity);

}  // namespace hs::resolved
