// SPDX-License-Identifier: MIT
// The "divided" particle-to-grid map of CFDEM: each sphere split into 29 equal-volume markers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/vec3.hpp"
#include "unresolved/dem/particle_store.hpp"
#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {

class DiffusionSmoothing;

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

  /// Locates the markers of the owned particles (threaded over particles), and sorts them by cell for
  /// for_each_cell(). Markers outside the box along a non-periodic axis, or in a cell with no fluid, are lumped onto
  /// the centre's cell (as CFDEM does with markers it cannot find).
  void locate(const ParticleStore& particles);
  [[nodiscard]] std::size_t size() const { return cells_.size() / kMarkersPerSphere; }
  /// Cell flat index of marker m of particle i.
  [[nodiscard]] std::size_t cell(std::size_t i, int m) const { return cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)]; }

  /// Particle-to-grid sums without races and with the bits of a serial loop: threaded over the cells that hold
  /// markers, f(cell, marker) is called for each marker k = i * kMarkersPerSphere + m of the cell (particle
  /// k / kMarkersPerSphere) in ascending k, the order in which a loop over particles and their markers would
  /// add them. So every sum comes out the same at any thread count, run to run.
  template <typename F>
  void for_each_cell(F&& f) const {
    const auto n = static_cast<std::int64_t>(occupied_.size());
#pragma omp parallel for schedule(static) if (n > kParallelCells)
    for (std::int64_t q = 0; q < n; ++q) {
      const std::size_t c = occupied_[static_cast<std::size_t>(q)];
      for (std::uint32_t e = start_[c]; e < start_[c + 1]; ++e) f(c, static_cast<std::size_t>(markers_[e]));
    }
  }

  /// eps = 1 - (solid volume in the cell) / (fluid volume of the cell), clipped at eps_min. With `smoothing` the
  /// solid fraction is smoothed before the clip (clipping first lost the volume of markers crowding a small cell:
  /// 11 % of the cells' volume in the D = 30 um tube at 15 cells across). Returns the solid volume dropped by the
  /// clipping, m^3 (zero when nothing was clipped; CFDEM only counts it, so do we).
  double void_fraction(const ParticleStore& particles, double eps_min, BlockField<double>& eps,
                       DiffusionSmoothing* smoothing = nullptr) const;
  /// Fluid volume of a cell (fluid fraction x dx^3), m^3.
  [[nodiscard]] double fluid_volume_m3(std::size_t cell) const { return grid_.fluid_fractions()[cell] * cell_volume_m3_; }

 private:
  /// Clips eps at eps_min in the fluid cells (1 in the others); returns the solid volume dropped, m^3.
  double clip_void_fraction(double eps_min, BlockField<double>& eps) const;
  void sort_by_cell(std::size_t n_cells);

  // Below this many occupied cells the sums run on one thread (an OpenMP region costs more than the loop).
  static constexpr std::int64_t kParallelCells = 4096;

  const FvmGrid& grid_;
  double cell_volume_m3_;
  std::vector<std::size_t> cells_;
  // The markers sorted by cell (a stable counting sort): those of cell c are markers_[start_[c] .. start_[c + 1]).
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> markers_;
  std::vector<std::size_t> occupied_;   // cells holding a marker, ascending
};

}  // namespace hs::unresolved
