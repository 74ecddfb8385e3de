// SPDX-License-Identifier: MIT
// The momentum solve (hypre BiCGSTAB, diagonal preconditioner) with its rows distributed over the ranks: the same
// solution as one rank holding the whole matrix, checked with a residual computed here on the gathered solution;
// new values of the same pattern reach hypre's off-rank block. Run at np 1, 2 and 4 (oversubscribed), z-slabs of
// the box, uneven on purpose.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "unresolved/fvm/distributed_rows.hpp"
#include "unresolved/fvm/model_pressure_matrix.hpp"
#include "unresolved/fvm/momentum_solver.hpp"

namespace hs::unresolved {
namespace {

using distributed_rows::gathered;
using distributed_rows::my_rows;
using distributed_rows::part_of;
using distributed_rows::RankRows;
using distributed_rows::rows_of;
using pressure_model::norm;
using pressure_model::residual_norm;

constexpr int kN = 16;
constexpr int kRows = kN * kN * kN;

/// An implicit-Euler convection-diffusion row per cell of a kN^3 box, in units of nu / dx^2: time term 1 (the viscous
/// number nu dt / dx^2 = 1), diffusion 1 per link, central convection F / 2 with a rotating velocity of cell Peclet
/// number up to `peclet` (non-symmetric, as the momentum predictor's), walls half a cell away on every side.
CsrMatrix momentum_matrix(double peclet) {
  const auto id = [](int i, int j, int k) { return (k * kN + j) * kN + i; };
  CsrMatrix a;
  a.rows = kRows;
  a.row_ptr.push_back(0);
  for (int k = 0; k < kN; ++k) {
    for (int j = 0; j < kN; ++j) {
      for (int i = 0; i < kN; ++i) {
        const double u[3] = {peclet * std::sin(0.4 * j), peclet * std::cos(0.3 * i), 0.5 * peclet * std::sin(0.2 * (i + j))};
        double diag = 1.0;
        std::vector<std::pair<int, double>> row;
        for (int ax = 0; ax < 3; ++ax) {
          for (const int s : {-1, 1}) {
            int n[3] = {i, j, k};
            n[ax] += s;
            const double conv = 0.5 * s * u[ax];
            if (n[ax] < 0 || n[ax] >= kN) {
              diag += 2.0;   // a wall half a cell away (its value goes to the right-hand side)
              continue;
            }
            diag += 1.0;
            row.emplace_back(id(n[0], n[1], n[2]), -1.0 + conv);
          }
        }
        row.emplace_back(id(i, j, k), diag);
        pressure_model::append_row(a, std::move(row));
      }
    }
  }
  return a;
}

std::vector<double> right_hand_side() {
  std::vector<double> b(static_cast<std::size_t>(kRows));
  for (std::size_t r = 0; r < b.size(); ++r) b[r] = std::sin(0.37 * static_cast<double>(r)) + 0.1;
  return b;
}

constexpr double kTolerance = 1e-10;

TEST(DistributedMomentumSolve, SolvesTheWholeSystemAsOneRankDoes) {
  const CsrMatrix whole = momentum_matrix(1.5);
  const std::vector<double> b = right_hand_side();
  const RankRows mine = my_rows(kN);

  MomentumSolver distributed(MPI_COMM_WORLD);
  distributed.set_matrix(rows_of(whole, mine));
  std::vector<double> x_part(static_cast<std::size_t>(mine.count), 0.0);
  const MomentumSolve solve = distributed.solve(part_of(b, mine), x_part, kTolerance, 500);
  EXPECT_GT(solve.iterations, 0);
  EXPECT_LE(solve.relative_residual, kTolerance);
  const std::vector<double> x = gathered(x_part);

  MomentumSolver alone(MPI_COMM_SELF);
  alone.set_matrix(whole);
  std::vector<double> x_alone(b.size(), 0.0);
  (void)alone.solve(b, x_alone, kTolerance, 500);

  // The residual computed here on the gathered solution meets the tolerance (1 % slack for the rounding of the
  // sums and for hypre's recursively updated residual, which drifts from the true one by ~ machine epsilon x
  // cond(A) ~ 1e-15 for this diagonally dominant matrix).
  EXPECT_LE(residual_norm(whole, b, x), 1.01 * kTolerance * norm(b));
  // Both solutions are within ||A^-1|| ||r|| of the exact one. The convecting velocity is divergence-free and
  // constant along its own axis, so the convection is skew and sym(A) = I + (diffusion) >= I: ||A^-1|| <= 1; and
  // ||A|| <= 16 (largest row sum, a corner cell), so ||x|| >= ||b|| / 16. Relative distance <= 2 x 16 x 1e-10.
  std::vector<double> diff(b.size());
  for (std::size_t r = 0; r < b.size(); ++r) diff[r] = x[r] - x_alone[r];
  EXPECT_LE(norm(diff), 3.2e-9 * norm(x_alone));
}

TEST(DistributedMomentumSolve, NewValuesOfTheSamePatternReachEveryBlock) {
  // The flux and the void fraction change every step, the pattern never: the values are written into hypre's
  // matrix in place, and the solve must be of the new matrix, also for entries in the off-rank block.
  const std::vector<double> b = right_hand_side();
  const RankRows mine = my_rows(kN);
  MomentumSolver solver(MPI_COMM_WORLD);
  solver.set_matrix(rows_of(momentum_matrix(1.5), mine));
  std::vector<double> x_part(static_cast<std::size_t>(mine.count), 0.0);
  (void)solver.solve(part_of(b, mine), x_part, kTolerance, 500);

  const CsrMatrix changed = momentum_matrix(-0.7);
  solver.set_values(rows_of(changed, mine).values);
  std::fill(x_part.begin(), x_part.end(), 0.0);
  (void)solver.solve(part_of(b, mine), x_part, kTolerance, 500);
  EXPECT_LE(residual_norm(changed, b, gathered(x_part)), 1.01 * kTolerance * norm(b));

  // The way the FVM assembly writes them: straight into hypre's storage at each entry's place (the preconditioner's
  // diagonal too).
  const CsrMatrix again = momentum_matrix(0.3);
  const CsrMatrix again_mine = rows_of(again, mine);
  const MatrixEntries entries = solver.entries();
  for (std::size_t q = 0; q < again_mine.values.size(); ++q) entries[solver.positions()[q]] = again_mine.values[q];
  std::fill(x_part.begin(), x_part.end(), 0.0);
  (void)solver.solve(part_of(b, mine), x_part, kTolerance, 500);
  EXPECT_LE(residual_norm(again, b, gathered(x_part)), 1.01 * kTolerance * norm(b));
}

TEST(DistributedMomentumSolve, ACappedSolveReportsItsTrueResidual) {
  const std::vector<double> b = right_hand_side();
  const RankRows mine = my_rows(kN);
  const CsrMatrix whole = momentum_matrix(1.5);
  MomentumSolver solver(MPI_COMM_WORLD);
  solver.set_matrix(rows_of(whole, mine));
  std::vector<double> x_part(static_cast<std::size_t>(mine.count), 0.0);
  const MomentumSolve solve = solver.solve(part_of(b, mine), x_part, kTolerance, 2);
  EXPECT_EQ(solve.iterations, 2);
  const double measured = residual_norm(whole, b, gathered(x_part)) / norm(b);
  EXPECT_GT(measured, kTolerance);
  EXPECT_NEAR(solve.relative_residual, measured, 1e-12 + 1e-9 * measured);
}

TEST(DistributedMomentumSolve, TheWholeMatrixOnEveryRankIsRefusedOnEveryRank) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) GTEST_SKIP() << "on one rank the whole matrix is the rank's own rows";
  MomentumSolver solver(MPI_COMM_WORLD);
  EXPECT_THROW(solver.set_matrix(momentum_matrix(1.5)), std::logic_error);
}

}  // namespace
}  // namespace hs::unresolved
