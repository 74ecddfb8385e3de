// SPDX-License-Identifier: MIT
// Per-step Hessian proxy with the membrane viscosity: assembly, refactorisation and the n x 3 solve.
#include "resolved/membrane/viscous_step_proxy.hpp"

namespace hs::resolved {

ViscousStepProxy::ViscousStepProxy(const Eigen::SparseMatrix<double>& h0, const MembraneViscosity& viscosity,
                                   double h_us)
    : viscosity_(viscosity), inv_h_(1.0 / h_us), n_(static_cast<int>(h0.rows())) {
  for (int k = 0; k < h0.outerSize(); ++k) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(h0, k); it; ++it) {
      for (int c = 0; c < 3; ++c) base_.emplace_back(3 * static_cast<int>(it.row()) + c, 3 * static_cast<int>(it.col()) + c, it.value());
    }
  }
  matrix_.resize(3 * n_, 3 * n_);
  rhs_.resize(3 * n_);
  sol_.resize(3 * n_);
}

void ViscousStepProxy::refresh(const Positions& x) {
  frozen_at_ = x;
  viscosity_.freeze(x);
  trip_ = base_;
  viscosity_.append_hessian(inv_h_, trip_);
  matrix_.setFromTriplets(trip_.begin(), trip_.end());
  if (!analysed_) {
    ldlt_.analyzePattern(matrix_);
    analysed_ = true;
  }
  ldlt_.factorize(matrix_);
}

void ViscousStepProxy::solve(const Positions& g, Positions& out) const {
  for (int i = 0; i < n_; ++i)
    for (int c = 0; c < 3; ++c) rhs_[3 * i + c] = g(i, c);
  sol_ = ldlt_.solve(rhs_);
  out.resize(n_, 3);
  for (int i = 0; i < n_; ++i)
    for (int c = 0; c < 3; ++c) out(i, c) = sol_[3 * i + c];
}

}  // namespace hs::resolved
