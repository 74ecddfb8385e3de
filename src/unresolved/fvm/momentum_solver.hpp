// SPDX-License-Identifier: MIT
// A momentum equation's linear solve: hypre BiCGSTAB with a Jacobi (inverse diagonal) preconditioner.
#pragma once

#include <mpi.h>

#include <memory>
#include <span>
#include <vector>

#include "unresolved/fvm/csr_matrix.hpp"
#include "unresolved/fvm/matrix_entries.hpp"

namespace hs::unresolved {

class HypreMatrix;
class HypreVector;

/// The outcome of MomentumSolver::solve: iterations, and ||b - A x|| / ||b|| at the end.
struct MomentumSolve {
  int iterations = 0;
  double relative_residual = 0.0;
};

/// Solves the (non-symmetric, diagonally dominant) momentum systems with hypre's BiCGSTAB preconditioned by the
/// inverse diagonal, which needs nothing beyond each rank's rows: the method of Eigen's
/// BiCGSTAB<DiagonalPreconditioner> it replaces, now on distributed rows. Every rank calls set_matrix() and solve()
/// with its own rows (collective calls; CsrMatrix's rank-order layout). The values live only in hypre: an assembly
/// writes them through entries() at positions().
class MomentumSolver {
 public:
  explicit MomentumSolver(MPI_Comm comm = MPI_COMM_WORLD);
  ~MomentumSolver();
  MomentumSolver(const MomentumSolver&) = delete;
  MomentumSolver& operator=(const MomentumSolver&) = delete;

  /// Hands over a matrix, pattern and values (a set-up: the solver's work vectors are allocated).
  void set_matrix(const CsrMatrix& a);
  /// Each entry of the matrix set last, in its entry order: its place in entries().
  [[nodiscard]] const std::vector<int>& positions() const;
  /// The values, to be rewritten in place (the predictor's coefficients change every step, the pattern never).
  [[nodiscard]] MatrixEntries entries() const;
  /// New values for the pattern set last, in its entry order (a copy: entries() spares it).
  void set_values(std::span<const double> values);
  /// y = A x (this rank's rows of both), with the values set last.
  void multiply(std::span<const double> x, std::span<double> y);
  /// Solves A x = b from the guess in x (this rank's rows) until ||b - A x|| <= tolerance ||b|| (Eigen's rule;
  /// hypre checks the true residual before it stops) or max_iterations. The caller judges the returned residual.
  MomentumSolve solve(std::span<const double> b, std::span<double> x, double tolerance, int max_iterations);

 private:
  MPI_Comm comm_;
  std::unique_ptr<HypreMatrix> a_;
  std::unique_ptr<HypreVector> b_, x_, r_;
  std::vector<int> diagonal_position_;   // each row's diagonal in entries()
  std::vector<double> inverse_diagonal_; // the preconditioner, refreshed from the values before every solve
  void* bicgstab_ = nullptr;             // HYPRE_Solver (hypre types stay out of this header)
};

}  // namespace hs::unresolved
