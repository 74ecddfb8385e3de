// SPDX-License-Identifier: MIT
// Schiller-Naumann drag on a rigid sphere at finite particle Reynolds number.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "closures/drag_closure.hpp"

namespace hs::closures {

/// Schiller & Naumann (1933), Z. Ver. Dtsch. Ing. 77:318, in CFDEM's form (SchillerNaumannDrag.C,
/// reference/unresolved-methods.md 3.2): C_d = max(0.44, 24/Re_p (1 + 0.15 Re_p^0.687)), Re_p = d |u_r| / nu.
/// correction = C_d Re_p / 24 = max(0.44 Re_p / 24, 1 + 0.15 Re_p^0.687). Declared valid on Re_p in [0, 1000]
/// (the correlation's fitted range; above ~990 the Newton plateau 0.44 takes over).
class SchillerNaumann final : public DragClosure {
 public:
  SchillerNaumann() : DragClosure("schiller_naumann", {{*find_input("re_p"), {0.0, 1000.0}}}) {}

 private:
  [[nodiscard]] double compute_drag_coefficient(const DragInputs& in) const override {
    if (!(in.re_p > 0.0)) return std::numeric_limits<double>::max();
    return std::max(0.44, 24.0 / in.re_p * (1.0 + 0.15 * std::pow(in.re_p, 0.687)));
  }
  [[nodiscard]] double compute_correction(const DragInputs& in) const override {
    const double re = std::max(in.re_p, 0.0);
    return std::max(0.44 * re / 24.0, 1.0 + 0.15 * std::pow(re, 0.687));
  }
};

}  // namespace hs::closures
