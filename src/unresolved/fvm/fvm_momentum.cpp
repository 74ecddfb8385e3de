// SPDX-License-Identifier: MIT
// FvmSolver: assembly and solution of the momentum equation on the staggered velocity nodes.
#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

double FvmSolver::face_average(const BlockField<double>& cell_field, int c, long idx) const {
  return 0.5 * (cell_field[static_cast<std::size_t>(idx - cell_field.stride(c))] + cell_field[static_cast<std::size_t>(idx)]);
}

/// Outward volume flux (m^3/s) through the face of the momentum control volume of node idx (component c)
/// towards direction dir, interpolated from the fluxes of the cell faces that the face straddles.
double FvmSolver::momentum_cv_flux(int c, long idx, int dir) const {
  const int a = dir / 2;
  const bool plus = dir % 2 == 1;
  const auto& phi = phi_[static_cast<std::size_t>(a)];
  const long sc = phi.stride(c);
  const long sa = phi.stride(a);
  auto at = [&](long i) { return phi[static_cast<std::size_t>(i)]; };
  if (a == c) return plus ? 0.5 * (at(idx) + at(idx + sc)) : -0.5 * (at(idx - sc) + at(idx));
  return plus ? 0.5 * (at(idx - sc + sa) + at(idx + sa)) : -0.5 * (at(idx - sc) + at(idx));
}

/// Viscosity factor on the link from velocity node idx (component c) towards dir: the cell the link crosses
/// (along c) or the mean of the four cells around the edge it crosses (across c), the usual staggered-grid
/// placement of a variable viscosity. A wall link takes the same cells (ghosts: zero gradient).
double FvmSolver::link_viscosity(int c, long idx, int dir) const {
  const int a = dir / 2;
  const bool plus = dir % 2 == 1;
  const long sc = visc_.stride(c);
  auto v = [&](long i) { return visc_[static_cast<std::size_t>(i)]; };
  if (a == c) return plus ? v(idx) : v(idx - sc);
  const long s = plus ? visc_.stride(a) : -visc_.stride(a);
  return 0.25 * (v(idx - sc) + v(idx) + v(idx - sc + s) + v(idx + s));
}

/// Factor of nu/dx^2 for link dir of a node (Shortley & Weller 1938): along an axis with neighbours
/// (or walls) at fractions t1 and t2 of a cell, u'' = 2/(t1 + t2) [(u_1 - u_P)/t1 + (u_2 - u_P)/t2] / dx^2,
/// which is 1 for the regular stencil. A zero-gradient (outlet) link counts as a full cell.
double shortley_weller(const auto& comp, int lid, int dir) {
  if (lid < 0) return 1.0;
  const auto& links = comp.links[static_cast<std::size_t>(lid)];
  auto fraction = [&](int d) {
    const NodeLink& l = links[static_cast<std::size_t>(d)];
    return l.type == NodeLink::Type::dirichlet ? l.theta : 1.0;
  };
  const int axis = dir / 2;
  return 2.0 / (fraction(dir) * (fraction(2 * axis) + fraction(2 * axis + 1)));
}

/// Momentum row of node P (per unit mass and volume, implicit Euler, linearised central convection):
///   (eps/dt + Ksl/rho) u_P + sum_l d_l (u_P - u_l) + sum_l F_l/(2V) (u_l - u_P)
///     = eps u_P^n/dt + (Ksl Us + f)/rho - eps G,     d_l = eps nu / dx^2 x shortley_weller(l),
/// where a wall link l holds u_l = u_wall at the fraction theta_l of the link.
/// The PISO diagonal A is the symmetric part (time, Ksl, viscous); convection goes to H. The projection uses
/// A0 = eps/dt + Ksl/rho instead, and H/A0 = u* + eps G p^n / A0 once the predictor has solved for u*.
void FvmSolver::assemble_momentum(int c, bool convection) {
  Component& comp = comp_[static_cast<std::size_t>(c)];
  const long rows = static_cast<long>(comp.node.size());
  const MatrixEntries val = comp.solver->entries();
  const double dt = piso_.dt_s;
  const double rho = fluid_.density_kg_m3;
  const double nu_h2 = fluid_.kinematic_viscosity_m2_s / (h_ * h_);
  const double inv_2v = 0.5 / (h_ * h_ * h_);
  const double g = c == drive_.axis ? drive_gradient_ : 0.0;
  const long sc = eps_.stride(c);
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
  for (long r = 0; r < rows; ++r) {
    const long idx = comp.node[static_cast<std::size_t>(r)];
    const double e = face_average(eps_, c, idx);
    const double ks = face_average(ksl_, c, idx);
    const double us = 0.5 * (us_[static_cast<std::size_t>(idx - sc)][c] + us_[static_cast<std::size_t>(idx)][c]);
    const double f = 0.5 * (force_[static_cast<std::size_t>(idx - sc)][c] + force_[static_cast<std::size_t>(idx)][c]);
    double diag = e / dt + ks / rho;
    double rhs = e * comp.x[r] / dt + (ks * us + f) / rho - e * g;
    double conv_diag = 0.0;
    const int lid = comp.link_id[static_cast<std::size_t>(r)];
    const auto& slot = comp.slot[static_cast<std::size_t>(r)];
    for (int dir = 0; dir < 6; ++dir) {
      if (slot[static_cast<std::size_t>(dir) + 1] == -2) continue;
      const double conv = convection ? momentum_cv_flux(c, idx, dir) * inv_2v : 0.0;
      const NodeLink link = lid < 0 ? NodeLink{} : comp.links[static_cast<std::size_t>(lid)][static_cast<std::size_t>(dir)];
      if (link.type == NodeLink::Type::neumann) continue;
      const double d = e * nu_h2 * shortley_weller(comp, lid, dir) * (variable_viscosity_ ? link_viscosity(c, idx, dir) : 1.0);
      diag += d;
      conv_diag -= conv;
      if (link.type == NodeLink::Type::active) {
        // A periodic axis of two cells: both of its links reach the same node, whose one entry holds their sum.
        const int at = slot[static_cast<std::size_t>(dir) + 1];
        const bool second_link = dir % 2 == 1 && slot[static_cast<std::size_t>(dir)] == at;
        val[at] = (second_link ? val[at] : 0.0) - d + conv;
      } else {
        rhs += (d - conv) * link.value;
      }
    }
    val[slot[0]] = diag + conv_diag;
    // The projection's diagonal leaves out the viscous links (see PressureCoupling).
    comp.a[r] = piso_.coupling == PressureCoupling::projection ? e / dt + ks / rho : diag;
    comp.b[r] = rhs;
  }
}

void FvmSolver::solve_momentum(int c) {
  Component& comp = comp_[static_cast<std::size_t>(c)];
  const long rows = static_cast<long>(comp.node.size());
  if (rows == 0) return;
  Eigen::VectorXd rhs(rows);
  const long sc = p_.stride(c);
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
  for (long r = 0; r < rows; ++r) {
    const long idx = comp.node[static_cast<std::size_t>(r)];
    const double grad_p = (p_[static_cast<std::size_t>(idx)] - p_[static_cast<std::size_t>(idx - sc)]) / h_;
    rhs[r] = comp.b[r] - face_average(eps_, c, idx) * grad_p;
  }
  Eigen::VectorXd x = comp.x;
  const MomentumSolve solve = solve_momentum_system(c, rhs, x, piso_.momentum_tolerance, piso_.momentum_max_iterations);
  // A capped solve within 100x the tolerance is kept (the next step starts from it); beyond, the step is wrong.
  if (!(solve.relative_residual < 100.0 * piso_.momentum_tolerance)) {
    throw hs::common::NumericalError(fmt::format(
        "FVM: momentum predictor (component {}) did not converge: residual {:.3g} after {} iterations at t = {:.6g} s",
        "xyz"[c], solve.relative_residual, solve.iterations, time_s_));
  }
  comp.x = x;
  stats_.momentum_iterations += solve.iterations;
}

MomentumSolve FvmSolver::solve_momentum_system(int c, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double tolerance,
                                               int max_iterations) {
  Component& comp = comp_[static_cast<std::size_t>(c)];
  const auto n = static_cast<std::size_t>(rhs.size());
  return comp.solver->solve({rhs.data(), n}, {x.data(), n}, tolerance, max_iterations);
}

/// Flow-rate control: the velocity change that one implicit step gives per unit change of the mean
/// gradient, u1 = -M^-1 eps (time, Ksl and viscous terms; an influence-matrix approach as in constant-flux
/// channel DNS). Holding the flow rate with it needs no under-relaxation at any viscous number dt nu/dx^2,
/// where a plug correction rAU dG (OpenFOAM meanVelocityForce) overshoots when nu dt/dx^2 >> 1.
void FvmSolver::compute_drive_response() {
  const int c = drive_.axis;
  Component& comp = comp_[static_cast<std::size_t>(c)];
  const long rows = static_cast<long>(comp.node.size());
  const double g = drive_gradient_;
  drive_gradient_ = 0.0;
  const Eigen::VectorXd x = comp.x;
  comp.x.setZero();
  assemble_momentum(c, false);
  Eigen::VectorXd rhs(rows);
  for (long r = 0; r < rows; ++r) rhs[r] = comp.b[r] - face_average(eps_, c, comp.node[static_cast<std::size_t>(r)]);
  drive_response_ = Eigen::VectorXd::Zero(rows);
  solve_momentum_system(c, rhs, drive_response_, 1e-10, 100 * piso_.momentum_max_iterations);
  comp.x = x;
  drive_gradient_ = g;
  const auto& ap = grid_.apertures(c);
  double flux = 0.0;
  for (long r = 0; r < rows; ++r) {
    const long idx = comp.node[static_cast<std::size_t>(r)];
    flux += face_average(eps_, c, idx) * ap[static_cast<std::size_t>(idx)] * h_ * h_ * drive_response_[r];
  }
  drive_response_flux_ = sum_over_ranks(flux) / static_cast<double>(global_node_count(c, c));
}

/// The viscous links of the momentum row without its eps: div(tau) = rho nu / dx^2 sum_l SW_l m_l (u_l - u_P) at every
/// active node, with the Shortley-Weller weights, link viscosities and wall values the fluid itself uses, so a
/// particle's V_p div(tau) is the fluid's own stress (issue #25), not a pointwise Laplacian of the interpolant.
void FvmSolver::update_viscous_force() {
  const double mu_h2 = fluid_.density_kg_m3 * fluid_.kinematic_viscosity_m2_s / (h_ * h_);
  for (int c = 0; c < 3; ++c) {
    const Component& comp = comp_[static_cast<std::size_t>(c)];
    const BlockField<double>& u = u_[static_cast<std::size_t>(c)];
    const long rows = static_cast<long>(comp.node.size());
    Eigen::VectorXd nodal(rows);
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
    for (long r = 0; r < rows; ++r) {
      const long idx = comp.node[static_cast<std::size_t>(r)];
      const int lid = comp.link_id[static_cast<std::size_t>(r)];
      const auto& slot = comp.slot[static_cast<std::size_t>(r)];
      const double up = u[static_cast<std::size_t>(idx)];
      double sum = 0.0;
      for (int dir = 0; dir < 6; ++dir) {
        if (slot[static_cast<std::size_t>(dir) + 1] == -2) continue;
        const NodeLink link = lid < 0 ? NodeLink{} : comp.links[static_cast<std::size_t>(lid)][static_cast<std::size_t>(dir)];
        if (link.type == NodeLink::Type::neumann) continue;
        const double w = shortley_weller(comp, lid, dir) * (variable_viscosity_ ? link_viscosity(c, idx, dir) : 1.0);
        const long nb = idx + (dir % 2 == 1 ? 1 : -1) * u.stride(dir / 2);
        const double ul = link.type == NodeLink::Type::active ? u[static_cast<std::size_t>(nb)] : link.value;
        sum += w * (ul - up);
      }
      nodal[r] = mu_h2 * sum;
    }
    scatter(c, nodal, viscous_force_[static_cast<std::size_t>(c)]);
  }
}

}  // namespace hs::unresolved
