// SPDX-License-Identifier: MIT
// The spectrin network's stress-free shape: an oblate spheroid mapped area for area onto the biconcave rest mesh.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "resolved/membrane/evans_fung_shape.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

/// Reduced volume v = V / (4 pi R_A^3 / 3), R_A = sqrt(A / 4 pi), of an oblate spheroid of polar-to-equatorial axis
/// ratio c/a in (0, 1] (1: the sphere).
[[nodiscard]] double oblate_spheroid_reduced_volume(double axis_ratio);

/// The axis ratio c/a of the oblate spheroid of reduced volume v in (0.2, 1].
[[nodiscard]] double oblate_spheroid_axis_ratio(double reduced_volume);

/// The vertices of `biconcave` (the generated Evans-Fung mesh in its own frame: axis z, centred) moved onto an oblate
/// spheroid of the given reduced volume and the mesh's area, each vertex keeping its azimuth and the area fraction
/// of the surface between it and its pole. The map keeps every ring's area, so the network's reference differs from
/// the biconcave shape by in-plane shear only (no local dilation, which the lipid bilayer forbids); the rim goes to
/// the equator. Scaled so the spheroid mesh's polyhedral area is the biconcave mesh's.
[[nodiscard]] std::vector<hs::common::Vec3> oblate_stress_free_vertices(const TriangleMesh& biconcave,
                                                                        const EvansFungShape& shape,
                                                                        double reduced_volume);

}  // namespace hs::resolved
