// SPDX-License-Identifier: MIT
// Interface of lift closures, in coefficient form.
#pragma once

#include "closures/closure.hpp"

namespace hs::closures {

/// The velocity a lift coefficient is normalised with: the slip u_f - u_p (Saffman-type lift), or the fluid
/// velocity u_f at the particle relative to the walls (the resolved RBC dataset, docs/coefficients.md).
enum class LiftVelocity { slip, flow };

/// Lift on one particle: F_L = (pi/8) rho_f d_p^2 C_l |u|^2 e, u the reference velocity (slip or flow) and e the unit
/// direction the coupling layer chooses (the radial unit vector in the seed paper; u_r x omega / |u_r x omega| for
/// Saffman-type lift). With LiftVelocity::flow the input re_p is d_p |u_f| / nu, as in the fit.
class LiftClosure : public Closure {
 public:
  [[nodiscard]] virtual LiftVelocity reference_velocity() const { return LiftVelocity::slip; }
  [[nodiscard]] double lift_coefficient(const LiftInputs& in) const {
    count(in);
    return compute_lift_coefficient(in);
  }

 protected:
  using Closure::Closure;
  [[nodiscard]] virtual double compute_lift_coefficient(const LiftInputs& in) const = 0;
};

}  // namespace hs::closures
