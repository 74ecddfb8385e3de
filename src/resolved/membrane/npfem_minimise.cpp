// SPDX-License-Identifier: MIT
// npFEM minimisation: L-BFGS with the constant proxy as initial inverse Hessian (Liu, Bouaziz & Kavan 2017) and
// the plain projective-dynamics iteration, both with the convergence tests of Palabos-npFEM (reference §3.3).
#include <algorithm>
#include <cmath>
#include <deque>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "resolved/membrane/npfem_solver.hpp"

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

}  // namespace

NpfemStepReport NpfemSolver::minimise(Positions& x, const Positions& y) {
  NpfemStepReport report;
  const double tol = settings_.gradient_tolerance * force_scale_pN_;
  Positions g, gt, xt;
  double fx = objective(x, y, g);
  require_finite(fx, 0);
  std::deque<Positions> s_hist, y_hist;
  std::deque<double> rho_hist, f_hist;
  report.stop_reason = "max_iterations";
  while (true) {
    if (max_row_norm(g) <= tol) {
      report.converged = true;
      report.stop_reason = "gradient";
      break;
    }
    if (report.iterations >= settings_.max_iterations) break;
    // Two-loop recursion with H0^-1 as the initial inverse Hessian.
    Positions q = g;
    std::vector<double> alpha(s_hist.size());
    for (int k = static_cast<int>(s_hist.size()) - 1; k >= 0; --k) {
      alpha[k] = rho_hist[k] * dot(s_hist[k], q);
      q -= alpha[k] * y_hist[k];
    }
    Positions d = apply_inverse_proxy(q);
    for (std::size_t k = 0; k < s_hist.size(); ++k) d += (alpha[k] - rho_hist[k] * dot(y_hist[k], d)) * s_hist[k];
    d = -d;
    double gd = dot(g, d);
    if (!(gd < 0.0)) {   // not a descent direction: restart from the proxy step
      s_hist.clear(), y_hist.clear(), rho_hist.clear();
      d = -apply_inverse_proxy(g);
      gd = dot(g, d);
    }
    double step = 1.0;
    double ft = 0.0;
    bool accepted = false;
    for (int j = 0; j <= settings_.line_search_halvings; ++j, step *= 0.5) {
      xt = x + step * d;
      ft = objective(xt, y, gt);
      if (std::isfinite(ft) && ft <= fx + armijo_c1 * step * gd && dot(gt, d) >= curvature_c2 * gd) {
        accepted = true;
        break;
      }
    }
    ++report.iterations;
    if (!accepted) {
      ++report.stagnations;
      if (!(ft < fx)) {   // no decrease at the smallest step either
        if (s_hist.empty() || report.stagnations >= max_stagnations) {
          report.stop_reason = "line_search";
          break;
        }
        s_hist.clear(), y_hist.clear(), rho_hist.clear();
        continue;
      }
    }
    require_finite(ft, report.iterations);
    const Positions s = xt - x;
    const Positions yk = gt - g;
    const double sy = dot(s, yk);
    if (sy > 1e-16 * std::sqrt(dot(s, s) * dot(yk, yk))) {   // keep only pairs with positive curvature
      s_hist.push_back(s), y_hist.push_back(yk), rho_hist.push_back(1.0 / sy);
      if (static_cast<int>(s_hist.size()) > settings_.lbfgs_history) {
        s_hist.pop_front(), y_hist.pop_front(), rho_hist.pop_front();
      }
    }
    x = xt;
    g = gt;
    fx = ft;
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

NpfemStepReport NpfemSolver::projective_dynamics(Positions& x, const Positions& y) {
  NpfemStepReport report;
  const double tol = settings_.gradient_tolerance * force_scale_pN_;
  Positions g;
  std::deque<double> f_hist;
  double fx = objective(x, y, g);
  report.stop_reason = "max_iterations";
  while (true) {
    require_finite(fx, report.iterations);
    if (max_row_norm(g) <= tol) {
      report.converged = true;
      report.stop_reason = "gradient";
      break;
    }
    if (report.iterations >= settings_.max_iterations) break;
    x -= apply_inverse_proxy(g);   // local projections are inside g; this is the global solve
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
