// SPDX-License-Identifier: MIT
// A CsrMatrix and its vectors as hypre ParCSR objects (IJ interface), shared by the pressure and momentum solvers.
// Internal to hs_fvm: only its .cpp files include hypre.
#pragma once

#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_mv.h>
#include <mpi.h>

#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "unresolved/fvm/csr_matrix.hpp"

namespace hs::unresolved {

/// hypre's IJ layout needs rank k's rows right after rank k-1's: a matrix handed over otherwise is a caller's bug
/// (the classic one: the whole matrix on every rank). Collective, so every rank throws std::logic_error (naming
/// `who`) or none does.
void check_row_layout(MPI_Comm comm, const CsrMatrix& a, std::string_view who);

/// This rank's rows of a hypre vector.
class HypreVector {
 public:
  HypreVector(MPI_Comm comm, int first_row, int rows);
  ~HypreVector();
  HypreVector(const HypreVector&) = delete;
  HypreVector& operator=(const HypreVector&) = delete;

  [[nodiscard]] HYPRE_ParVector par() const;
  [[nodiscard]] std::span<double> values();
  void assign(std::span<const double> v);
  void copy_to(std::span<double> v) const;

 private:
  HYPRE_IJVector ij_ = nullptr;
  int rows_;
};

/// A CsrMatrix assembled into hypre. Its values can be replaced in place while the pattern stays (no new
/// assembly: hypre splits the rows into a diagonal block and an off-rank block, and each entry's place in them is
/// found once).
class HypreMatrix {
 public:
  HypreMatrix(MPI_Comm comm, const CsrMatrix& a);
  ~HypreMatrix();
  HypreMatrix(const HypreMatrix&) = delete;
  HypreMatrix& operator=(const HypreMatrix&) = delete;

  [[nodiscard]] HYPRE_ParCSRMatrix par() const;
  [[nodiscard]] const CsrMatrix& csr() const { return a_; }
  [[nodiscard]] long global_rows() const { return global_rows_; }
  /// Whether `a` has this matrix's rows and pattern and every entry was located in hypre's blocks.
  [[nodiscard]] bool same_pattern(const CsrMatrix& a) const;
  /// Writes new values for the same pattern (same_pattern() must hold; values in the CsrMatrix's entry order).
  void update_values(std::span<const double> values);
  /// ||b|| and ||b - A x|| over all ranks, r a work vector (hypre's own product fetches the neighbours' x).
  [[nodiscard]] std::pair<double, double> rhs_and_residual_norms(const HypreVector& b, const HypreVector& x,
                                                                 HypreVector& r) const;

 private:
  [[nodiscard]] std::vector<int> entry_positions() const;

  CsrMatrix a_;
  std::vector<int> position_;   // each entry's place in hypre's diagonal block (0..) or after it the off-rank one
  HYPRE_IJMatrix ij_ = nullptr;
  long global_rows_ = 0;
};

}  // namespace hs::unresolved
