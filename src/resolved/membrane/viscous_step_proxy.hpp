// SPDX-License-Identifier: MIT
// The npFEM Hessian proxy of a step with membrane viscosity: the constant proxy plus the viscous Hessian at x_n.
#pragma once

#include <vector>

#include <Eigen/SparseCholesky>

#include "resolved/membrane/membrane_energy.hpp"
#include "resolved/membrane/membrane_viscosity.hpp"

namespace hs::resolved {

/// H = kron(H0, I3) + K_v(x_n) / h: the solver's constant proxy H0 (n x n, the same for x, y, z) and the exact Hessian
/// of the step's viscous potential R(x - x_n) / h (MembraneViscosity::append_hessian). The viscous part couples the
/// coordinates through each triangle's plane and turns with the cell, so H is refactorised at a recent geometry
/// (every NpfemSettings::viscous_proxy_refresh_steps steps; the pattern is analysed once). Without it L-BFGS stopped
/// at its cap on 92 % of the steps of the Ca = 1 shear case (the constant per-coordinate approximation: the viscous
/// term outweighs the mass term 180x there and is zero along the normal).
class ViscousStepProxy {
 public:
  ViscousStepProxy(const Eigen::SparseMatrix<double>& h0, const MembraneViscosity& viscosity, double h_us);
  /// Refactorises with the viscous Hessian at the geometry x (kept: frozen_at()).
  void refresh(const Positions& x);
  [[nodiscard]] const Positions& frozen_at() const { return frozen_at_; }
  /// out = H^-1 g for an n x 3 block g (out is resized).
  void solve(const Positions& g, Positions& out) const;
  [[nodiscard]] bool ok() const { return ldlt_.info() == Eigen::Success; }

 private:
  MembraneViscosity viscosity_;   // a copy, frozen at the proxy's own geometry
  Positions frozen_at_;
  double inv_h_;
  int n_;
  bool analysed_ = false;
  std::vector<Eigen::Triplet<double>> base_;   // kron(H0, I3)
  std::vector<Eigen::Triplet<double>> trip_;   // base_ + the viscous part, rebuilt each step
  Eigen::SparseMatrix<double> matrix_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  mutable Eigen::VectorXd rhs_;
  mutable Eigen::VectorXd sol_;
};

}  // namespace hs::resolved
