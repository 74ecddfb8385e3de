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
#include "unresolved/fvm/matrix_entries.hpp"

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

/// A CsrMatrix assembled into hypre (no copy is kept: three momentum matrices and the pressure one would each be
/// held twice). Its values can be replaced in place while the pattern stays: hypre splits the rows into a block of
/// this rank's columns and one of the others', and each entry's place in them is found once.
class HypreMatrix {
 public:
  HypreMatrix(MPI_Comm comm, const CsrMatrix& a);
  ~HypreMatrix();
  HypreMatrix(const HypreMatrix&) = delete;
  HypreMatrix& operator=(const HypreMatrix&) = delete;

  [[nodiscard]] HYPRE_ParCSRMatrix par() const;
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] int first_row() const { return first_row_; }
  [[nodiscard]] long global_rows() const { return global_rows_; }
  /// Each entry's place in entries(), in the CsrMatrix's entry order.
  [[nodiscard]] const std::vector<int>& positions() const { return position_; }
  [[nodiscard]] MatrixEntries entries() const;
  /// Writes new values for the pattern the matrix was built with (values in its entry order).
  void update_values(std::span<const double> values);
  /// ||b|| and ||b - A x|| over all ranks, r a work vector (hypre's own product fetches the neighbours' x).
  [[nodiscard]] std::pair<double, double> rhs_and_residual_norms(const HypreVector& b, const HypreVector& x,
                                                                 HypreVector& r) const;

 private:
  [[nodiscard]] std::vector<int> entry_positions(const CsrMatrix& a) const;

  int rows_ = 0;
  int first_row_ = 0;
  long global_rows_ = 0;
  std::vector<int> position_;   // each entry's place in entries()
  HYPRE_IJMatrix ij_ = nullptr;
};

}  // namespace hs::unresolved
