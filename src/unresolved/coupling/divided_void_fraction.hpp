// SPDX-License-Identifier: MIT
// The "divided" particle-to-grid map of CFDEM: each sphere split into 29 equal-volume markers.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "common/vec3.hpp"
#include "unresolved/dem/particle_store.hpp"
#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {

inline constexpr int kMarkersPerSphere = 29;

/// Marker offsets for a sphere of unit radius (unresolved-methods.md sec. 2, CFDEM dividedVoidFraction): the
/// centre, then two equal-volume shells split at r = (1/29)^(1/3) and (15/29)^(1/3), each with 14 markers at
/// its volume-centroid radius: 8 diagonal directions and the 6 axis directions.
[[nodiscard]] const std::array<hs::common::Vec3, kMarkersPerSphere>& divided_markers();

/// Where each owned particle's 29 markers fell: cell flat indices (BlockField::index) of the FvmGrid cells.
/// Every particle-to-grid sum (void fraction, Us, Ksl, forces) uses these same weights (1/29 each), so that
/// what the particles give the fluid and what the fluid gives the particles balance exactly.
class DividedMap {
 public:
  explicit DividedMap(const FvmGrid& grid);

  /// Locates the markers of the owned particles. Markers outside the box along a non-periodic axis, or in a
  /// cell with no fluid, are lumped onto the centre's cell (as CFDEM does with markers it cannot find).
  void locate(const ParticleStore& particles);
  [[nodiscard]] std::size_t size() const { return cells_.size() / kMarkersPerSphere; }
  /// Cell flat index of marker m of particle i.
  [[nodiscard]] std::size_t cell(std::size_t i, int m) const { return cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)]; }

  /// eps = 1 - (solid volume in the cell) / (fluid volume of the cell), clipped at eps_min. Returns the solid
  /// volume dropped by the clipping, m^3 (zero when nothing was clipped; CFDEM only counts it, so do we).
  double void_fraction(const ParticleStore& particles, double eps_min, BlockField<double>& eps) const;
  /// Fluid volume of a cell (fluid fraction x dx^3), m^3.
  [[nodiscard]] double fluid_volume_m3(std::size_t cell) const { return grid_.fluid_fractions()[cell] * cell_volume_m3_; }

 private:
  const FvmGrid& grid_;
  double cell_volume_m3_;
  std::vector<std::size_t> cells_;
};

}  // namespace hs::unresolved
