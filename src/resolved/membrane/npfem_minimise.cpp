// SPDX-License-Identifier: MIT
// npFEM minimisation: L-BFGS with the constant proxy as initial inverse Hessian (Liu, Bouaziz & Kavan 2017) and
// the plain projective-dynamics iteration, both with the convergence tests of Palabos-npFEM (reference §3.3).
#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

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

/// The last m (s, y) pairs of L-BFGS and the two-loop recursion (Nocedal & Wright 2006, Alg. 7.4) with the
/// prefactored proxy as the initial inverse Hessian (Liu et al. 2017).
class LbfgsHistory {
 public:
  explicit LbfgsHistory(int m) : m_(m) {}
  void clear() { s_.clear(), y_.clear(), rho_.clear(); }
  [[nodiscard]] bool empty() const { return s_.empty(); }
  /// Keeps the pair only if its curvature s.y is positive (otherwise the update would not be positive definite).
  void push(Positions s, Positions y) {
    const double sy = dot(s, y);
    if (!(sy > 1e-16 * std::sqrt(dot(s, s) * dot(y, y)))) return;
    s_.push_back(std::move(s)), y_.push_back(std::move(y)), rho_.push_back(1.0 / sy);
    if (static_cast<int>(s_.size()) > m_) s_.pop_front(), y_.pop_front(), rho_.pop_front();
  }
  template <typename InverseProxy>
  [[nodiscard]] Positions direction(const Positions& g, const InverseProxy& apply_h0_inverse) const {
    Positions q = g;
    std::vector<double> alpha(s_.size());
    for (int k = static_cast<int>(s_.size()) - 1; k >= 0; --k) {
      alpha[k] = rho_[k] * dot(s_[k], q);
      q -= alpha[k] * y_[k];
    }
    Positions r = apply_h0_inverse(q);
    for (std::size_t k = 0; k < s_.size(); ++k) r += (alpha[k] - rho_[k] * dot(y_[k], r)) * s_[k];
    return -r;
  }

 private:
  int m_;
  std::deque<Positions> s_, y_;
  std::deque<double> rho_;
};

}  // namespace

NpfemSolver::LineSearchResult NpfemSolver::line_search(const Positions& x, const Positions& d, const Positions& y,
                                                       double fx, double gd, Positions& xt, Positions& gt) {
  double step = 1.0;
  double ft = 0.0;
  for (int j = 0; j <= settings_.line_search_halvings; ++j, step *= 0.5) {
    xt = x + step * d;
    ft = objective(xt, y, gt);
    if (std::isfinite(ft) && ft <= fx + armijo_c1 * step * gd && dot(gt, d) >= curvature_c2 * gd) return {ft, true};
  }
  return {ft, false};
}

NpfemStepReport NpfemSolver::minimise(Positions& x, const Positions& y) {
  NpfemStepReport report;
  const double tol = settings_.gradient_tolerance * force_scale_pN_;
  Positions g, gt, xt;
  double fx = objective(x, y, g);
  require_finite(fx, 0);
  LbfgsHistory history(settings_.lbfgs_history);
  std::deque<double> f_hist;
  report.stop_reason = "max_iterations";
  while (true) {
    if (max_row_norm(g) <= tol) {
      report.converged = true;
      report.stop_reason = "gradient";
      break;
    }
    if (report.iterations >= settings_.max_iterations) break;
    Positions d = history.direction(g, [this](const Positions& q) { return apply_inverse_proxy(q); });
    double gd = dot(g, d);
    if (!(gd < 0.0)) {   // not a descent direction: restart from the proxy step
      history.clear();
      d = -apply_inverse_proxy(g);
      gd = dot(g, d);
    }
    const LineSearchResult ls = line_search(x, d, y, fx, gd, xt, gt);
    ++report.iterations;
    if (!ls.accepted) {
      ++report.stagnations;
      if (!(ls.objective < fx)) {   // no decrease at the smallest step either
        if (history.empty() || report.stagnations >= max_stagnations) {
          report.stop_reason = "line_search";
          break;
        }
        history.clear();
        continue;
      }
    }
    require_finite(ls.objective, report.iterations);
    history.push(xt - x, gt - g);
    x = xt;
    g = gt;
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
