// SPDX-License-Identifier: MIT
// Smoothing of the coupling's cell fields over a physical length, so that the particles' footprint on the grid
// does not shrink as the grid is refined.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

#include "common/vec3.hpp"
#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {

/// One implicit diffusion step q_s - l^2 lap(q_s) = q over the fluid cells (CFDEMcoupling's constDiffSmoothing:
/// D = l^2 / dt for one time step; Pirker et al. 2011, Radl & Sundaresan 2014; Sun & Xiao 2015, Int J Multiphase
/// Flow 72:233, show such diffusion is kernel smoothing). The discrete operator is written in flux form with one
/// symmetric coefficient per open face (its open area fraction, zero through walls, wrapped across periodic
/// faces), so:
///  - it conserves sum V_c q_c over the fluid cells (V_c the cell's fluid volume): what the particles put on the
///    grid stays there (solid volume, exchanged momentum);
///  - it keeps the values within their old bounds (an M-matrix): eps stays in [eps_min, 1];
///  - away from walls the spread of a plane source, sum x^2 q / sum q, is 2 l^2 on every grid (the discrete
///    Laplacian has the continuous one's second moment), so the footprint is l, not a number of cells.
/// Solved by Jacobi-preconditioned conjugate gradients to a relative residual of 1e-13 (the conservation and
/// the exchange bookkeeping then hold to round-off; the coupling also measures and returns any imbalance).
/// The operator is assembled once (the mesh is static). Up to kDirectMaxRows fluid cells it is also factorised once
/// (sparse LDL^T, AMD ordering), and each smoothing is two triangular solves, checked against the same 1e-13
/// relative residual (CG from the start if ever above it); on larger grids, or with Method::conjugate_gradient, CG.
/// On z-slabs split over several ranks (the grid's slabs()) each rank holds the rows of its block's cells and, as
/// ghost rows, the fluid cells of the neighbours' planes next to it; the CG exchanges those every iteration and sums
/// its dot products over the ranks (docs/cfd-dem.md "Distributed CFD-DEM" step 4). No factor then: the result agrees
/// with one rank's to the solver's tolerance, not to the bit. On one slab the whole-grid path runs unchanged.
/// smooth_together() solves several fields at once: one pass over the factor or the operator for all of them (in
/// CG each field keeps its own scalars and stopping test), so each result is what smooth() alone gives, to the
/// solver's tolerance.
class DiffusionSmoothing {
 public:
  enum class Method { automatic, conjugate_gradient };
  DiffusionSmoothing(const FvmGrid& grid, double length_m, Method method = Method::automatic);

  /// Smooths a density field (per unit fluid volume) in place, interior fluid cells only; other cells untouched.
  void smooth(BlockField<double>& q);
  void smooth(BlockField<hs::common::Vec3>& q);
  /// Smooths all the given fields (each as smooth() does) in one multi-right-hand-side solve; at most
  /// kMaxColumns values a cell in all (a vector field counts 3).
  void smooth_together(std::initializer_list<BlockField<double>*> scalars,
                       std::initializer_list<BlockField<hs::common::Vec3>*> vectors);
  static constexpr int kMaxColumns = 8;
  /// The direct factor's limit. A 3D grid's LDL^T fill grows about as rows^(4/3) (AMD on a periodic 7-point box:
  /// 1.4 MB at 2000 rows, 12 MB at 8000, 54 MB and 3 s to factorise at 20000); beyond it, CG. Was 10,000, where a
  /// field's two triangular solves stream the whole factor and were expected to no longer beat CG by much; but in the
  /// D = 30 um tube at 15 cells across (10,600 rows, l / dx 1.4) the CG smoothing took 134 ms of each step (68% of
  /// it), so the factor is kept up to the 20-cells-across tube (~25,000 rows).
  static constexpr std::size_t kDirectMaxRows = 40000;
  /// Whether the rows are spread over several ranks (collective smoothing, CG).
  [[nodiscard]] bool distributed() const { return halo_ != nullptr; }
  /// Whether smoothing uses the factor (false: CG).
  [[nodiscard]] bool direct() const { return factor_ != nullptr; }

  [[nodiscard]] double length_m() const { return length_m_; }
  /// CG iterations of the last smooth() (the largest over the fields smoothed together; 0 by the factor).
  [[nodiscard]] int last_iterations() const { return last_iterations_; }

 private:
  /// Solves A x_j = V q_j for the K compact vectors q_j (fluid cells; q[r * K + j]), in place; returns the most
  /// iterations any column took.
  template <std::size_t K>
  int solve(std::vector<double>& q);
  int solve_columns(std::vector<double>& q, int columns);
  /// The factor's solve of the same system; false if a column's residual is above the CG's tolerance.
  bool solve_direct(std::vector<double>& q, int columns);
  struct Factor;   // Eigen's LDL^T, kept out of this header
  struct Halo;     // distributed: the ghost rows and the rows they copy
  /// Distributed: fills the ghost rows of the `columns`-wide vector x from the neighbours (identity otherwise).
  void exchange_ghost_rows(std::vector<double>& x, std::size_t columns) const;
  /// Distributed: sums the values over the ranks in place (identity otherwise).
  template <std::size_t N>
  void sum_over_ranks(std::array<double, N>& values) const;

  double length_m_;
  std::vector<std::size_t> cell_index_;   // compact row -> BlockField flat index
  std::vector<double> volume_;            // fluid volume of each row, m^3
  std::vector<double> diagonal_;          // V_c + l^2 dx sum of the row's face coefficients
  std::vector<double> inverse_diagonal_;  // the Jacobi preconditioner
  // The off-diagonal part, CSR: neighbours of row r are neighbour_[row_start_[r] .. row_start_[r + 1]).
  std::vector<std::size_t> row_start_;
  std::vector<std::size_t> neighbour_;
  std::vector<double> coefficient_;       // l^2 dx (open area fraction): positive, symmetric
  std::vector<double> x_, r_, z_, p_, ap_;   // CG work vectors, rows x columns (row-major: one row's columns together)
  std::shared_ptr<const Factor> factor_;   // null: CG
  std::shared_ptr<const Halo> halo_;       // null: every row here
  int last_iterations_ = 0;
};

}  // namespace hs::unresolved
