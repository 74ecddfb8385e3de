// SPDX-License-Identifier: MIT
// The pressure equation's linear solve: hypre PCG preconditioned by BoomerAMG on a CSR matrix.
#pragma once

#include <mpi.h>

#include <vector>

namespace hs::unresolved {

/// Symmetric positive definite matrix in CSR form, rows 0..rows-1 of this rank.
struct CsrMatrix {
  int rows = 0;
  std::vector<int> row_ptr;     // size rows + 1
  std::vector<int> cols;
  std::vector<double> values;
};

/// Stopping rule as OpenFOAM's: stop when ||r|| <= tolerance * ||b|| (absolute level) or when
/// ||r|| <= rel_tol * ||r0|| (relative drop from the initial guess), whichever comes first.
struct SolveTolerance {
  double tolerance = 1e-6;
  double rel_tol = 0.05;
  int max_iterations = 1000;
};

/// PCG + BoomerAMG (hypre). The AMG hierarchy is built by set_matrix() and reused by every solve until
/// the next set_matrix(): the pressure matrix only changes when the void fraction or Ksl change.
/// Needs MPI to be initialised (the hemoscale executable and the fvm tests do it).
class PressureSolver {
 public:
  explicit PressureSolver(MPI_Comm comm = MPI_COMM_WORLD);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  void set_matrix(const CsrMatrix& a);
  /// Solves A x = b from the initial guess in x; returns the number of PCG iterations.
  int solve(const std::vector<double>& b, std::vector<double>& x, const SolveTolerance& tol);
  [[nodiscard]] const CsrMatrix& matrix() const { return a_; }

 private:
  void destroy();

  MPI_Comm comm_;
  CsrMatrix a_;
  void* ij_matrix_ = nullptr;   // HYPRE_IJMatrix (hypre types stay out of this header)
  void* ij_b_ = nullptr;
  void* ij_x_ = nullptr;
  void* pcg_ = nullptr;         // HYPRE_Solver
  void* amg_ = nullptr;
};

}  // namespace hs::unresolved
