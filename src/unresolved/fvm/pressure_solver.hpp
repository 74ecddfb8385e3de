// SPDX-License-Identifier: MIT
// The pressure equation's linear solve: hypre PCG preconditioned by BoomerAMG on a CSR matrix.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "unresolved/fvm/csr_matrix.hpp"

namespace hs::unresolved {

class HypreMatrix;
class HypreVector;

/// Stopping rule as OpenFOAM's: stop when ||r|| <= tolerance * ||b|| (absolute level) or when
/// ||r|| <= rel_tol * ||r0|| (relative drop from the initial guess), whichever comes first.
struct SolveTolerance {
  double tolerance = 1e-6;
  double rel_tol = 0.05;
  int max_iterations = 1000;
};

/// When set_matrix() may keep the AMG hierarchy of an earlier matrix as the preconditioner of a new one with the
/// same pattern (the CFD-DEM pressure matrix: its coefficients eps^2 / A move with the particles every step, its
/// pattern never). PCG still stops on the new matrix's own residual, so the solution meets the same tolerance;
/// only the iteration count can grow as the hierarchy ages. Rebuilt when either bound below is passed.
struct AmgReuse {
  bool enabled = true;
  // A solve with a reused hierarchy took more than growth x (the most iterations of a solve with a fresh one) +
  // slack: the next set_matrix() rebuilds. 1.5: each extra PCG iteration costs about 1/10 of a BoomerAMG set-up
  // on the 7-point Laplacian (measured, docs/cfd-dem.md), so a few are cheaper than a set-up every step.
  double max_iteration_growth = 1.5;
  int iteration_slack = 2;
  // Largest relative change of a diagonal entry against the matrix the hierarchy was built on, beyond which it is
  // rebuilt whatever the iterations say. Off by default: in dense suspensions some cell's void fraction always
  // moves that much as spheres cross grid cells, so a bound of 0.5 rebuilt the hierarchy on every step of the
  // bifurcation study (Ht 0.2) for 11% fewer PCG iterations at 43% more fluid-step time (docs/cfd-dem.md); the
  // iteration bound above already catches a hierarchy that stopped paying.
  double max_diagonal_change = std::numeric_limits<double>::infinity();
};

/// What a checkpoint keeps of a PressureSolver, so that a resumed run solves with the hierarchy the uninterrupted
/// run would have used: the values of the matrix it was built on (its pattern is the next matrix's: the grid's) and
/// the reuse bookkeeping. BoomerAMG's set-up is deterministic, so a rebuild on those values is the same hierarchy.
struct AmgCheckpoint {
  bool built = false;                 // a hierarchy existed (the same on every rank; a rank may hold no rows)
  std::vector<double> setup_values;   // this rank's rows' entries
  std::int64_t fresh_iterations = 0;
  bool fresh = false;
  bool stale = false;
  std::int64_t setups = 0;
  std::int64_t reuses = 0;
};

/// PCG + BoomerAMG (hypre). The AMG hierarchy is built by set_matrix() and reused by every solve until
/// the next set_matrix(), and by later matrices of the same pattern as AmgReuse allows.
/// Every rank of the communicator calls set_matrix() and solve() with its own rows (collective calls); vectors hold
/// this rank's rows only. Needs MPI to be initialised (the hemoscale executable and the fvm tests do it).
class PressureSolver {
 public:
  explicit PressureSolver(MPI_Comm comm = MPI_COMM_WORLD, AmgReuse reuse = {});
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  void set_matrix(const CsrMatrix& a);
  /// Solves A x = b from the initial guess in x (this rank's rows of both); returns the number of PCG iterations.
  int solve(const std::vector<double>& b, std::vector<double>& x, const SolveTolerance& tol);
  /// BoomerAMG set-ups so far, and set_matrix() calls that kept the hierarchy.
  [[nodiscard]] long setups() const { return setups_; }
  [[nodiscard]] long reuses() const { return reuses_; }

  [[nodiscard]] AmgCheckpoint checkpoint() const;
  /// Takes a checkpoint(): the next set_matrix() first rebuilds the saved hierarchy on its own pattern.
  void restore(AmgCheckpoint saved);

 private:
  void destroy();
  void build(const CsrMatrix& a);
  /// restore()'s deferred half: the saved hierarchy, built on a's pattern with the saved values.
  void rebuild_restored(const CsrMatrix& a);
  /// Whether a's pattern is the hierarchy's and neither AmgReuse bound is passed.
  [[nodiscard]] bool can_reuse(const CsrMatrix& a) const;
  [[nodiscard]] bool same_pattern(const CsrMatrix& a) const;

  MPI_Comm comm_;
  AmgReuse reuse_;
  std::unique_ptr<HypreMatrix> a_;
  CsrMatrix setup_matrix_;                   // the matrix the hierarchy was built on (a_ holds the latest values)
  std::unique_ptr<HypreVector> b_, x_, r_;   // right-hand side, solution, residual work vector
  std::vector<double> setup_diagonal_;       // diagonal of the matrix the hierarchy was built on
  mutable std::vector<double> diagonal_work_;   // can_reuse's copy of the new diagonal (kept: no allocation a step)
  int fresh_iterations_ = 0;                 // most iterations of a solve while the hierarchy was fresh
  bool fresh_ = false;                       // the matrix now set is the one the hierarchy was built on
  bool stale_ = false;                       // a reused hierarchy passed the iteration bound
  long setups_ = 0;
  long reuses_ = 0;
  std::unique_ptr<AmgCheckpoint> restored_;   // set by restore() until the next set_matrix()
  void* pcg_ = nullptr;                      // HYPRE_Solver (hypre types stay out of this header)
  void* amg_ = nullptr;
};

}  // namespace hs::unresolved
