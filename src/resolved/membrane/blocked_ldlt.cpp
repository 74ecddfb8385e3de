// SPDX-License-Identifier: MIT
// Blocked back-solves of a sparse LDL^T factor: permute, L, D, L^T, permute back, three coordinates per row.
#include "resolved/membrane/blocked_ldlt.hpp"

namespace hs::resolved {

BlockedLdlt::BlockedLdlt(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& factor)
    : n_(static_cast<int>(factor.vectorD().size())) {
  const auto& l = factor.matrixL().nestedExpression();   // unit lower triangular, compressed by column
  col_start_.reserve(static_cast<std::size_t>(n_) + 1);
  for (int j = 0; j < n_; ++j) {
    col_start_.push_back(static_cast<int>(row_.size()));
    for (Eigen::SparseMatrix<double>::InnerIterator it(l, j); it; ++it) {
      if (it.row() <= j) continue;   // the unit diagonal (stored or not) is implicit
      row_.push_back(static_cast<int>(it.row()));
      value_.push_back(it.value());
    }
  }
  col_start_.push_back(static_cast<int>(row_.size()));
  for (int j = 0; j < n_; ++j) inv_diag_.push_back(1.0 / factor.vectorD()[j]);
  perm_.resize(static_cast<std::size_t>(n_));
  const auto& p = factor.permutationP();
  for (int i = 0; i < n_; ++i) perm_[static_cast<std::size_t>(i)] = p.size() > 0 ? p.indices()[i] : i;
  work_.assign(static_cast<std::size_t>(n_) * stride, 0.0);
}

void BlockedLdlt::solve(const Positions& b, Positions& out) const {
  double* w = work_.data();
  for (int i = 0; i < n_; ++i) {
    double* wi = w + stride * perm_[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) wi[c] = b(i, c);
  }
  for (int j = 0; j < n_; ++j) {   // L z = P b
    const double* wj = w + stride * j;
    for (int p = col_start_[static_cast<std::size_t>(j)]; p < col_start_[static_cast<std::size_t>(j) + 1]; ++p) {
      double* wi = w + stride * row_[static_cast<std::size_t>(p)];
      const double l = value_[static_cast<std::size_t>(p)];
      for (int c = 0; c < stride; ++c) wi[c] -= l * wj[c];
    }
  }
  for (int j = 0; j < n_; ++j)
    for (int c = 0; c < stride; ++c) w[stride * j + c] *= inv_diag_[static_cast<std::size_t>(j)];
  for (int j = n_ - 1; j >= 0; --j) {   // L^T u = D^-1 z
    double acc[stride] = {w[stride * j], w[stride * j + 1], w[stride * j + 2], w[stride * j + 3]};
    for (int p = col_start_[static_cast<std::size_t>(j)]; p < col_start_[static_cast<std::size_t>(j) + 1]; ++p) {
      const double* wi = w + stride * row_[static_cast<std::size_t>(p)];
      const double l = value_[static_cast<std::size_t>(p)];
      for (int c = 0; c < stride; ++c) acc[c] -= l * wi[c];
    }
    for (int c = 0; c < stride; ++c) w[stride * j + c] = acc[c];
  }
  out.resize(n_, 3);
  for (int i = 0; i < n_; ++i) {
    const double* wi = w + stride * perm_[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) out(i, c) = wi[c];
  }
}

}  // namespace hs::resolved
