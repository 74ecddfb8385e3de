// SPDX-License-Identifier: MIT
// Back-solves of a once-factorised sparse LDL^T on all three coordinates at once (the npFEM Hessian proxy).
#pragma once

#include <vector>

#include <Eigen/SparseCholesky>

#include "resolved/membrane/membrane_energy.hpp"

namespace hs::resolved {

/// Copies the factor of an Eigen SimplicialLDLT (P A P^T = L D L^T) and solves A X = B for an n x 3 block B in one
/// sweep over the factor per triangular solve, with x, y, z of a row side by side (Eigen solves column by column and
/// allocates temporaries). Same arithmetic as Eigen's solve up to the order of round-off.
class BlockedLdlt {
 public:
  BlockedLdlt() = default;
  explicit BlockedLdlt(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& factor);
  /// out = A^-1 b (out is resized; it may not alias b).
  void solve(const Positions& b, Positions& out) const;

 private:
  static constexpr int stride = 4;    // x, y, z and one pad: one 256-bit lane per row
  int n_ = 0;
  std::vector<int> col_start_;        // strictly lower part of L, compressed by column
  std::vector<int> row_;
  std::vector<double> value_;
  std::vector<double> inv_diag_;      // 1 / D
  std::vector<int> perm_;             // (P b)[perm_[i]] = b[i]
  mutable std::vector<double> work_;  // n x stride
};

}  // namespace hs::resolved
