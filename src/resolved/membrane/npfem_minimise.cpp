// SPDX-License-Identifier: MIT
// npFEM minimisation: L-BFGS with the constant proxy as initial inverse Hessian (Liu, Bouaziz & Kavan 2017) and
// the plain projective-dynamics iteration, both with the convergence tests of Palabos-npFEM (reference §3.3).
// The L-BFGS pairs persist from step to step (LbfgsMemory in the solver's workspace).
#include <algorithm>
#include <cmath>
#include <deque>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "resolved/membrane/npfem_workspace.hpp"

namespace hs::resolved {
namespace {

constexpr double armijo_c1 = 1e-4;        // Palabos-npFEM gamma (sufficient decrease)
constexpr double curvature_c2 = 0.9;      // Palabos-npFEM gamma2 (Wolfe curvature)
constexpr int max_stagnations = 7;        // Palabos-npFEM: stop after 7 failed line searches
constexpr int objective_window = 5;       // Palabos-npFEM: relative spread of the last 5 objective values
constexpr double objective_rel_tol = 1e-12;  // near double round-off of an objective summed over ~10^3 terms
constexpr double pN_to_N = 1e-12;

double dot(const Positions& a, const Positions& b) { return (a.array() * b.array()).sum(); }

void require_finite(double value, int iteration) {
  if (!std::isfinite(value)) {
    throw hs::common::NumericalError(fmt::format(
        "npFEM: the objective became {} at iteration {}; the membrane solve diverged (reduce the time step or forces)",
        value, iteration));
  }
}

bool objective_stalled(std::deque<double>& history, double value) {
  history.push_back(value);
  if (static_cast<int>(history.size()) > objective_window) history.pop_front();
  if (static_cast<int>(history.size()) < objective_window) return false;
  const auto [lo, hi] = std::minmax_element(history.begin(), history.end());
  return *hi - *lo <= objective_rel_tol * std::max(1.0, std::abs(value));
}

// A direction d whose predicted decrease -grad.d is below the objective's round-off cannot be followed: the objective
// cannot tell the trial points apart, so the line search fails for want of precision, not of descent, and the step is
// as converged as objective_stalled would find it (the same limit). Measured where it happens (shear case at Ca 11.7,
// an npFEM step every 0.48 us, 390 failed searches): -grad.d <= 4e-14 |f| every time, the trial objectives ~1e-14 |f|
// above f at the smallest step, the gradient 1.0-4.7x its tolerance.
bool descent_below_round_off(double gd, double value) {
  return -gd <= objective_rel_tol * std::max(1.0, std::abs(value));
}

}  // namespace

NpfemSolver::LineSearchResult NpfemSolver::line_search(const Positions& x, const Positions& d, const Positions& y,
                                                       double fx, double gd, Positions& xt, Positions& gt) {
  double step = 1.0;
  double ft = 0.0;
  for (int j = 0; j <= settings_.line_search_halvings; ++j, step *= 0.5) {
    xt.noalias() = x + step * d;
    ft = objective(xt, y, gt);
    if (std::isfinite(ft) && ft <= fx + armijo_c1 * step * gd && dot(gt, d) >= curvature_c2 * gd) return {ft, true};
  }
  return {ft, false};
}

NpfemStepReport NpfemSolver::minimise(Positions& x, const Positions& y, Positions& g, double fx) {
  NpfemStepReport report;
  const double tol = settings_.gradient_tolerance * force_scale_pN_;
  require_finite(fx, 0);
  Workspace& w = *work_;
  LbfgsMemory& history = w.history;   // kept from the previous steps
  const LbfgsMemory::InverseProxy h0_inverse = [this](const Positions& q, Positions& out) { apply_inverse_proxy(q, out); };
  std::deque<double> f_hist;
  report.stop_reason = "max_iterations";
  while (true) {
    if (max_row_norm(g) <= tol) {
      report.converged = true;
      report.stop_reason = "gradient";
      break;
    }
    if (report.iterations >= settings_.max_iterations) break;
    history.direction(g, h0_inverse, w.dir);
    double gd = dot(g, w.dir);
    if (!(gd < 0.0)) {   // not a descent direction: restart from the proxy step
      history.clear();
      apply_inverse_proxy(g, w.dir);
      w.dir = -w.dir;
      gd = dot(g, w.dir);
    }
    const LineSearchResult ls = line_search(x, w.dir, y, fx, gd, w.xt, w.gt);
    ++report.iterations;
    if (!ls.accepted) {
      ++report.stagnations;
      if (!(ls.objective < fx)) {   // no decrease at the smallest step either
        if (history.empty() || report.stagnations >= max_stagnations) {
          report.converged = descent_below_round_off(gd, fx);
          report.stop_reason = report.converged ? "objective" : "line_search";
          break;
        }
        history.clear();
        continue;
      }
    }
    require_finite(ls.objective, report.iterations);
    w.s.noalias() = w.xt - x;
    w.yk.noalias() = w.gt - g;
    history.push(w.s, w.yk);
    x.swap(w.xt);
    g.swap(w.gt);
    fx = ls.objective;
    if (objective_stalled(f_hist, fx)) {
      report.converged = true;
      report.stop_reason = "objective";
      break;
    }
    if (report.stagnations >= max_stagnations) {
      report.stop_reason = "line_search";
      break;
    }
  }
  report.gradient_max_N = max_row_norm(g) * pN_to_N;
  return report;
}

NpfemStepReport NpfemSolver::projective_dynamics(Positions& x, const Positions& y, Positions& g, double fx) {
  NpfemStepReport report;
  const double tol = settings_.gradient_tolerance * force_scale_pN_;
  std::deque<double> f_hist;
  report.stop_reason = "max_iterations";
  while (true) {
    require_finite(fx, report.iterations);
    if (max_row_norm(g) <= tol) {
      report.converged = true;
      report.stop_reason = "gradient";
      break;
    }
    if (report.iterations >= settings_.max_iterations) break;
    apply_inverse_proxy(g, work_->dir);   // local projections are inside g; this is the global solve
    x -= work_->dir;
    fx = objective(x, y, g);
    ++report.iterations;
    if (objective_stalled(f_hist, fx)) {
      report.converged = true;
      report.stop_reason = "objective";
      break;
    }
  }
  report.gradient_max_N = max_row_norm(g) * pN_to_N;
  return report;
}

}  // namespace hs::resolved
