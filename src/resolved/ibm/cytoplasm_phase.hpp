// SPDX-License-Identifier: MIT
// The cytoplasm as the lattice's second fluid phase: the nodes inside a cell's membrane, kept up to date.
#pragma once

#include <array>
#include <span>

#include "common/vec3.hpp"
#include "resolved/lbm/fluid_lattice.hpp"

namespace hs::resolved {

/// Marks the lattice nodes a closed membrane encloses (enclosed_nodes) as the lattice's inner phase, which relaxes
/// with the cytoplasm's viscosity (FluidLattice::set_inner_collision). The indicator is sharp: a node is inside or
/// outside, as in Lehmann, Mueller & Gekle 2020 (Int J Numer Meth Fluids 92:1463); the IBM's diffuse interface then
/// carries the velocity across, and the viscosity jumps between the last node inside and the first outside.
class CytoplasmPhase {
 public:
  /// pre: `lattice` initialised, with set_inner_collision() done. Global node (i, j, k) sits at origin + dx (i, j, k).
  CytoplasmPhase(FluidLattice& lattice, const common::Vec3& lattice_origin_m, double dx_m);

  /// Makes the nodes of this rank's block that the mesh encloses (vertex positions in SI, unwrapped) the inner phase,
  /// and only those. Every rank holds the whole membrane, so this is not collective.
  void update(std::span<const common::Vec3> x_m, std::span<const std::array<int, 3>> triangles);
  /// Inner nodes on this rank since the last update.
  [[nodiscard]] std::size_t inner_nodes() const { return lattice_.inner_node_count(); }

 private:
  FluidLattice& lattice_;
  common::Vec3 origin_m_;
  double dx_m_;
};

}  // namespace hs::resolved
