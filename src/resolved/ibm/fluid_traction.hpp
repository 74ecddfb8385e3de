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
};

/// Per-vertex traction force in lattice units (rho dx^4/dt^2), and the diagnostics of how it was read.
struct TractionResult {
  std::vector<common::Vec3> force_lu;
  double mean_pressure_lu = 0.0;   // area-weighted mean of c_s^2 rho over the sampled vertices (removed)
  int vertices_without_fluid = 0;  // vertices whose outermost stencil node is a wall node (force set to zero)
};

/// 1-ring neighbour lists (vertex itself excluded) of a triangle mesh with `vertex_count` vertices.
std::vector<std::vector<int>> one_ring(int vertex_count, std::span<const std::array<int, 3>> triangles);

/// Component-wise median over each vertex and its 1-ring (Palabos-npFEM's FILTERING, resolved-methods.md 1.4 step 6).
std::vector<common::Vec3> median_filter(std::span<const common::Vec3> values, const std::vector<std::vector<int>>& ring);

/// For each vertex: the node of the IBM stencil furthest outside along the normal gives sigma' (viscous stress from
/// the populations with the Guo forcing correction) and p = c_s^2 rho; F = A sigma'.n - (p - p_mean) A n with p_mean
/// the area-weighted cell mean. No kernel interpolation (Palabos-npFEM: interpolation there was unstable).
/// Collective: every rank returns the same forces. `ring` empty = no median filter.
TractionResult fluid_traction(const ImmersedBoundary& ibm, const FluidLattice& lattice, const SurfaceSample& surface,
                              const std::vector<std::vector<int>>& ring);

}  // namespace hs::resolved
