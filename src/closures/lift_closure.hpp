// SPDX-License-Identifier: MIT
// Interface of lift closures, in coefficient form.
#pragma once

#include "closures/closure.hpp"

namespace hs::closures {

/// Lift on one particle: F_L = (pi/8) rho_f d_p^2 C_l |u_r|^2 e, with e the unit direction the coupling layer
/// chooses (the radial unit vector in the seed paper; u_r x omega / |u_r x omega| for Saffman-type lift).
class LiftClosure : public Closure {
 public:
  [[nodiscard]] double lift_coefficient(const LiftInputs& in) const {
    count(in);
    return compute_lift_coefficient(in);
  }

 protected:
  using Closure::Closure;
  [[nodiscard]] virtual double compute_lift_coefficient(const LiftInputs& in) const = 0;
};

}  // namespace hs::closures
