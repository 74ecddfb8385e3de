// SPDX-License-Identifier: MIT
// The pressure solve with its rows distributed over the ranks (hypre's IJ layout, CsrMatrix::first_row): the same
// solution as one rank holding the whole matrix, checked with a residual computed here on the gathered solution,
// not with hypre's own; the AMG hierarchy kept across matrices also when entries sit in the off-rank block.
// Run at np 1, 2 and 4 (oversubscribed): slabs of the box along z, uneven on purpose (every rank but the last one
// plane short of an even split).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "unresolved/fvm/distributed_rows.hpp"
#include "unresolved/fvm/model_pressure_matrix.hpp"
#include "unresolved/fvm/pressure_solver.hpp"

namespace hs::unresolved {
namespace {

using distributed_rows::gathered;
using distributed_rows::part_of;
using distributed_rows::RankRows;
using distributed_rows::rows_of;
using pressure_model::kN;
using pressure_model::norm;
using pressure_model::pressure_matrix;
using pressure_model::residual_norm;
using pressure_model::void_fraction;

constexpr int kRows = kN * kN * kN;

std::vector<double> right_hand_side() {
  std::vector<double> b(static_cast<std::size_t>(kRows));
  for (std::size_t r = 0; r < b.size(); ++r) b[r] = std::sin(0.37 * static_cast<double>(r)) + 0.1;
  return b;
}

const SolveTolerance kTight{.tolerance = 1e-10, .rel_tol = 0.0, .max_iterations = 500};

TEST(DistributedPressureSolve, SolvesTheWholeSystemAsOneRankDoes) {
  const CsrMatrix whole = pressure_matrix(void_fraction(0.0));
  const std::vector<double> b = right_hand_side();
  const RankRows mine = distributed_rows::my_rows(kN);

  PressureSolver distributed(MPI_COMM_WORLD);
  distributed.set_matrix(rows_of(whole, mine));
  std::vector<double> x_part(static_cast<std::size_t>(mine.count), 0.0);
  const int iterations = distributed.solve(part_of(b, mine), x_part, kTight);
  EXPECT_GT(iterations, 0);
  const std::vector<double> x = gathered(x_part);

  PressureSolver alone(MPI_COMM_SELF);
  alone.set_matrix(whole);
  std::vector<double> x_alone(b.size(), 0.0);
  (void)alone.solve(b, x_alone, kTight);

  // The gathered solution meets the whole system's tolerance, ||A x - b|| <= 1e-10 ||b||, computed here (1 % slack
  // for the rounding of the two sums). The preconditioner differs with the rank count (hybrid Gauss-Seidel is
  // Jacobi across ranks), so the two solutions agree to cond(A) x 2e-10 relative, not to round-off; cond(A) ~ 500
  // for this operator (amg_reuse_test): 1e-7 bounds it.
  EXPECT_LE(residual_norm(whole, b, x), 1.01e-10 * norm(b));
  std::vector<double> diff(b.size());
  for (std::size_t r = 0; r < b.size(); ++r) diff[r] = x[r] - x_alone[r];
  EXPECT_LE(norm(diff), 1e-7 * norm(x_alone));
}

TEST(DistributedPressureSolve, KeepsTheHierarchyAndUpdatesTheOffRankEntries) {
  // The particles move: every coefficient changes, the pattern does not. The reused hierarchy must solve the new
  // matrix, so the new values must reach both of hypre's blocks (an off-rank entry left at its old value shows as a
  // residual of the new system far above the tolerance).
  const std::vector<double> b = right_hand_side();
  const RankRows mine = distributed_rows::my_rows(kN);
  PressureSolver solver(MPI_COMM_WORLD);
  solver.set_matrix(rows_of(pressure_matrix(void_fraction(0.0)), mine));
  std::vector<double> x_part(static_cast<std::size_t>(mine.count), 0.0);
  (void)solver.solve(part_of(b, mine), x_part, kTight);

  const CsrMatrix moved = pressure_matrix(void_fraction(0.33));
  solver.set_matrix(rows_of(moved, mine));
  EXPECT_EQ(solver.setups(), 1);
  EXPECT_EQ(solver.reuses(), 1);
  std::fill(x_part.begin(), x_part.end(), 0.0);
  (void)solver.solve(part_of(b, mine), x_part, kTight);
  EXPECT_LE(residual_norm(moved, b, gathered(x_part)), 1.01e-10 * norm(b));
}

TEST(DistributedPressureSolve, ARestoredSolverFollowsTheSavedOneAlsoWithARankWithoutRows) {
  // The restart contract of amg_reuse_test on several ranks, the last one holding no rows (a slab all solid): it has
  // no values to save, yet must rebuild the saved hierarchy with the others (the set-up is collective).
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int holders = std::max(1, size - 1);
  const auto first_plane = [&](int r) { return std::min(kN, r * kN / holders); };
  const RankRows mine{first_plane(rank) * kN * kN, (first_plane(rank + 1) - first_plane(rank)) * kN * kN};
  const std::vector<double> b = part_of(right_hand_side(), mine);

  PressureSolver uninterrupted(MPI_COMM_WORLD);
  std::vector<double> x(b.size(), 0.0);
  uninterrupted.set_matrix(rows_of(pressure_matrix(void_fraction(0.0)), mine));
  (void)uninterrupted.solve(b, x, kTight);
  uninterrupted.set_matrix(rows_of(pressure_matrix(void_fraction(0.2)), mine));
  (void)uninterrupted.solve(b, x, kTight);
  PressureSolver resumed(MPI_COMM_WORLD);
  resumed.restore(uninterrupted.checkpoint());

  const CsrMatrix next = rows_of(pressure_matrix(void_fraction(0.4)), mine);
  uninterrupted.set_matrix(next);
  resumed.set_matrix(next);
  std::vector<double> x_resumed = x;
  EXPECT_EQ(resumed.solve(b, x_resumed, kTight), uninterrupted.solve(b, x, kTight));
  EXPECT_EQ(x_resumed, x);   // bit for bit on every rank
  EXPECT_EQ(resumed.setups(), 1);
  EXPECT_EQ(resumed.reuses(), 2);
}

TEST(DistributedPressureSolve, TheWholeMatrixOnEveryRankIsRefusedOnEveryRank) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) GTEST_SKIP() << "on one rank the whole matrix is the rank's own rows";
  // Every rank passes rows from 0: all of them throw (none is left waiting in a collective call).
  PressureSolver solver(MPI_COMM_WORLD);
  EXPECT_THROW(solver.set_matrix(pressure_matrix(void_fraction(0.0))), std::logic_error);
}

}  // namespace
}  // namespace hs::unresolved
