// SPDX-License-Identifier: MIT
// Interface of drag closures, in coefficient form and as a correction to Stokes drag.
#pragma once

#include "closures/closure.hpp"

namespace hs::closures {

/// Drag on one particle. Conventions (reference/unresolved-methods.md 3.2): u_r = u_f - u_p,
///   F_d = (pi/8) rho_f d_p^2 C_d |u_r| u_r  =  3 pi mu d_p u_r * correction,   correction = C_d Re_p / 24.
/// Solvers should call correction(): it stays finite as Re_p -> 0 for the baselines, and gives the implicit
/// coefficient beta_p = 3 pi mu d_p * correction directly. Both calls count the evaluation.
class DragClosure : public Closure {
 public:
  [[nodiscard]] double drag_coefficient(const DragInputs& in) const {
    count(in);
    return compute_drag_coefficient(in);
  }
  [[nodiscard]] double correction(const DragInputs& in) const {
    count(in);
    return compute_correction(in);
  }

 protected:
  using Closure::Closure;
  [[nodiscard]] virtual double compute_drag_coefficient(const DragInputs& in) const = 0;
  [[nodiscard]] virtual double compute_correction(const DragInputs& in) const {
    return compute_drag_coefficient(in) * in.re_p / 24.0;
  }
};

}  // namespace hs::closures
