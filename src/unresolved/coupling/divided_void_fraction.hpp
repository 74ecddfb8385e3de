// SPDX-License-Identifier: MIT
// The "divided" particle-to-grid map of CFDEM: each sphere split into 29 equal-volume markers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
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

/// Where each particle's 29 markers fell: cell flat indices (BlockField::index) of the FvmGrid cells.
/// Every particle-to-grid sum (void fraction, Us, Ksl, forces) uses these same weights (1/29 each), so that
/// what the particles give the fluid and what the fluid gives the particles balance exactly.
///
/// On z-slabs (the grid's slabs(), docs/cfd-dem.md "Distributed CFD-DEM" step 4) a block deposits every marker that
/// falls in one of its own cells, of its owned particles and of the neighbours' (remote ghosts, DemSlabs), and each
/// cell adds its spheres' shares in ascending particle id: the order of one rank holding every particle, so the
/// block's sums are that rank's, sliced, to the bit, without a reverse exchange. A marker in a neighbour's cell is
/// left to the neighbour, where the particle is a ghost (the ghost layer is a cut-off, wider than a sphere).
class DividedMap {
 public:
  explicit DividedMap(const FvmGrid& grid);

  /// Locates the markers of the owned particles and, on slabs, of the remote ghosts (threaded over particles), and
  /// sorts them by cell for for_each_cell(). A marker outside the box along a non-periodic axis, or in a cell with no
  /// fluid, is lumped onto the centre's cell (as CFDEM does with markers it cannot find). On slabs z is not wrapped:
  /// a marker beyond the seam belongs to the periodic image of its particle, which a neighbour (or, on one slab,
  /// this block) holds as a remote ghost.
  void locate(const ParticleStore& particles);
  /// Owned particles located (the first size() rows of the store).
  [[nodiscard]] std::size_t size() const { return n_owned_; }
  /// A marker that falls in another block's cell (cell() on slabs only).
  static constexpr std::size_t kElsewhere = static_cast<std::size_t>(-1);
  /// Cell flat index of marker m of the store's row i (owned, or on slabs a remote ghost), or kElsewhere.
  [[nodiscard]] std::size_t cell(std::size_t i, int m) const {
    const std::uint32_t c = cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)];
    return c == kNowhere ? kElsewhere : c;
  }

  /// Whether row i's centre lies in one of this block's cells (every owned row on one rank; on slabs an owned
  /// particle may have drifted into a neighbour's plane since the last rebuild, and a remote ghost into this block's):
  /// the fluid is sampled at a particle by the one block holding its centre.
  [[nodiscard]] bool centred_here(std::size_t i) const { return cell(i, 0) != kElsewhere; }   // marker 0: the centre

  /// Particle-to-grid sums without races and with the bits of a serial loop: threaded over the cells that hold
  /// markers, f(cell, row, markers) is called once for each sphere with markers in the cell (row: the store's row of
  /// the sphere; markers: how many of its 29 fell there, so its share is markers / 29), in ascending id, the order of
  /// a loop over the particles by id and the distinct cells of their markers. So every sum comes out the same at any
  /// thread count, run to run, and (on slabs) at any rank count. (One call per sphere and cell, not per marker: a
  /// sphere smaller than a cell puts its 29 markers in ~3 cells.)
  template <typename F>
  void for_each_cell(F&& f) const {
    const auto n = static_cast<std::int64_t>(occupied_.size());
#pragma omp parallel for schedule(static) if (n > kParallelCells)
    for (std::int64_t q = 0; q < n; ++q) {
      const std::size_t c = occupied_[static_cast<std::size_t>(q)];
      for (std::uint32_t e = start_[c]; e < start_[c + 1]; ++e) {
        f(c, static_cast<std::size_t>(rows_[e]), static_cast<int>(markers_[e]));
      }
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
  /// Where a marker at x of a particle whose centre's cell is `centre` (global index) is added: a flat index or
  /// kElsewhere.
  [[nodiscard]] std::size_t marker_cell(const hs::common::Vec3& x, const std::array<long, 3>& centre) const;
  /// The global cell of x: periodic x and y wrapped, z wrapped only without slabs; nothing outside the box.
  [[nodiscard]] std::optional<std::array<long, 3>> global_cell(const hs::common::Vec3& x) const;
  /// Whether the global cell g has fluid: this block's fluid fraction, or beyond its planes the cached one.
  [[nodiscard]] bool has_fluid(const std::array<long, 3>& g) const;
  /// The flat index of global cell g if it is one of this block's, else kElsewhere.
  [[nodiscard]] std::size_t local_index(const std::array<long, 3>& g) const;
  /// Where row i's markers fall, for a sphere at x (radius r) whose centre's global cell is `centre`.
  void locate_markers(std::size_t i, const hs::common::Vec3& x, double r, const std::array<long, 3>& centre);
  /// The same when the sphere's bounding cube lies in this block's cells, inside the box (no wrap, nothing lumped
  /// for leaving it): each marker's cell from its position by the same arithmetic as global_cell(), minus the checks.
  /// False (nothing written) when the cube does not.
  bool locate_markers_inside(std::size_t i, const hs::common::Vec3& x, double r, const std::array<long, 3>& centre);
  /// by_id_ sorted by (id, row): a stable two-pass radix sort on the id's 32 bits when every id fits them.
  void sort_rows_by_id(const std::vector<std::int64_t>& id);
  /// Caches which cells have fluid in the `planes` planes on either side of this block (slabs only).
  void cache_neighbour_fluid(int planes);
  void sort_by_cell(std::size_t n_cells);

  // Below this many occupied cells the sums run on one thread (an OpenMP region costs more than the loop).
  static constexpr std::int64_t kParallelCells = 4096;

  const FvmGrid& grid_;
  double cell_volume_m3_;
  bool slabs_ = false;
  std::size_t n_owned_ = 0;
  // Per store row and marker: the cell's flat index, kNowhere where not here (or not located). 32 bits: the map is
  // written and read several times a step, and a million spheres' markers are 116 MB at this width.
  static constexpr std::uint32_t kNowhere = UINT32_MAX;
  std::vector<std::uint32_t> cells_;
  std::vector<std::uint32_t> by_id_;     // the rows located, by ascending id
  std::vector<std::uint32_t> id_scratch_;   // sort_rows_by_id()'s second buffer
  // The spheres sorted by cell (a stable counting sort in by_id_ order): the rows of the spheres with markers in cell
  // c are rows_[start_[c] .. start_[c + 1]), and markers_[e] how many of rows_[e]'s markers are there.
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> rows_;
  std::vector<std::uint8_t> markers_;
  std::vector<std::vector<std::uint32_t>> thread_counts_;   // sort_by_cell()'s per-thread counts, kept between calls
  struct Pair {   // one sphere's markers in one cell
    std::uint32_t cell;
    std::uint32_t row;
    std::uint8_t markers;
  };
  std::vector<std::vector<Pair>> thread_pairs_;   // sort_by_cell()'s pairs of each thread's spheres, kept likewise
  std::vector<std::size_t> occupied_;   // cells holding a marker, ascending
  // Slabs: fluid flags of the cached planes below (plane first - 1 - d at d) and above (first + n + d), x fastest.
  int cached_planes_ = 0;
  std::vector<std::uint8_t> fluid_below_, fluid_above_;
};

}  // namespace hs::unresolved
