// SPDX-License-Identifier: MIT
// Stokes drag on a rigid sphere, the creeping-flow limit of every drag law.
#pragma once

#include <limits>

#include "closures/drag_closure.hpp"

namespace hs::closures {

/// Stokes (1851): F = 3 pi mu d_p u_r, i.e. C_d = 24 / Re_p and correction = 1.
/// Valid for Re_p << 1; declared valid on [0, 1] (White, Viscous Fluid Flow, 3rd ed., sec. 3-9: within ~10%
/// of measured C_d up to Re_p ~ 1).
class StokesDrag final : public DragClosure {
 public:
  StokesDrag() : DragClosure("stokes", {{*find_input("re_p"), {0.0, 1.0}}}) {}

 private:
  [[nodiscard]] double compute_drag_coefficient(const DragInputs& in) const override {
    return in.re_p > 0.0 ? 24.0 / in.re_p : std::numeric_limits<double>::max();
  }
  [[nodiscard]] double compute_correction(const DragInputs&) const override { return 1.0; }
};

}  // namespace hs::closures
