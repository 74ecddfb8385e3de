// SPDX-License-Identifier: MIT
// The membrane's external force from the fluid stress (Palabos-npFEM, resolved-methods.md 1.4 steps 1-6).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "resolved/ibm/immersed_boundary.hpp"

namespace hs::resolved {

/// The membrane surface seen by the fluid, lattice units (positions in global lattice coordinates, unwrapped).
struct SurfaceSample {
  std::span<const common::Vec3> x_lu;
  std::span<const common::Vec3> normal;      // unit outward vertex normals
  std::span<const double> area_lu;           // vertex areas, lu^2
  std::span<const std::array<int, 3>> triangles;   // needed by TractionArea::sampled_surface
};

/// Which area each sampled stress acts on.
///  membrane: the vertex's own area A_v n_v (Palabos-npFEM). The stress is read 1-3 lu outside the membrane, where
///    it has already decayed (roughly as (a / (a + d))^2 around a body of size a), so the membrane receives only
///    28 % (dx = 1 um) to 46 % (dx = 0.5 um) of the hydrodynamic force (docs/resolved-coupling.md).
///  sampled_surface: the vertex's area vector on the surface parallel to the membrane at its sampling distance.
///    In Stokes flow the stress flux through any surface enclosing the body and the spread IBM force is the force
///    on the body, so the tractions then add up to it whatever the resolution. But the parallel surface of a thin
///    disc at d ~ 2 lu grows the rim's areas ~6x against the faces', and a stiff cell in shear then turned against
///    the vorticity (measured, docs/resolved-coupling.md): right in total, wrong in distribution.
///  scaled_membrane (default): the membrane's own area vectors, all multiplied by one factor per cell, the ratio
///    of the sampled parallel surface's total area to the membrane's. Palabos-npFEM's distribution (which turns the
///    disc the right way) with the total restored to the flux estimate.
enum class TractionArea { membrane, sampled_surface, scaled_membrane };

/// Per-vertex traction force in lattice units (rho dx^4/dt^2), and the diagnostics of how it was read.
struct TractionResult {
  std::vector<common::Vec3> force_lu;
  double mean_pressure_lu = 0.0;   // area-weighted mean of c_s^2 rho over the sampled vertices (removed)
  int vertices_without_fluid = 0;  // vertices whose outermost stencil node is a wall node (force set to zero)
  double mean_sample_distance_lu = 0.0;   // mean distance of the sample nodes outside the membrane along the normal
  std::vector<double> sample_distance_lu;  // per vertex: its sample node's distance outside the membrane along the normal
  /// Per vertex: its share of the volume the sampling surface encloses (cell + the shell out to its sample node),
  /// lu^3. A body-force drive acts on that fluid, and the sampled tractions do not see it (CouplingSettings).
  std::vector<double> enclosed_volume_lu;
};

/// Area vectors (1/3 of each adjacent triangle's vector area) of the mesh whose vertex v sits at
/// x_v + offset_v n_v. They sum to zero on a closed mesh.
std::vector<common::Vec3> offset_area_vectors(std::span<const common::Vec3> x, std::span<const common::Vec3> normal,
                                              std::span<const double> offset, std::span<const std::array<int, 3>> triangles);

/// 1-ring neighbour lists (vertex itself excluded) of a triangle mesh with `vertex_count` vertices.
std::vector<std::vector<int>> one_ring(int vertex_count, std::span<const std::array<int, 3>> triangles);

/// Component-wise median over each vertex and its 1-ring (Palabos-npFEM's FILTERING, resolved-methods.md 1.4 step 6).
std::vector<common::Vec3> median_filter(std::span<const common::Vec3> values, const std::vector<std::vector<int>>& ring);

/// For each vertex: the node of the IBM stencil furthest outside along the normal gives sigma' (viscous stress from
/// the populations with the Guo forcing correction) and p = c_s^2 rho; F = sigma'.S - (p - p_mean) S, with S the
/// area vector chosen by `area` and p_mean the area-weighted cell mean. No kernel interpolation (Palabos-npFEM:
/// interpolation there was unstable). Collective: every rank returns the same forces. `ring` empty = no median filter.
TractionResult fluid_traction(const ImmersedBoundary& ibm, const FluidLattice& lattice, const SurfaceSample& surface,
                              const std::vector<std::vector<int>>& ring, TractionArea area);

}  // namespace hs::resolved
