// SPDX-License-Identifier: MIT
// The dimensionless groups every closure takes (DESIGN.md "Units"), computed once by the coupling layer.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace hs::closures {

/// All inputs a closure may use; a closure reads only those it declares. Sign conventions as in the seed paper
/// sec. 4 (reference/unresolved-methods.md section 0).
struct ClosureInputs {
  double re_p = 0.0;         // particle Reynolds number d_p |u_p - u_f| / nu
  double re_shear = 0.0;     // shear Reynolds number gammadot d_p^2 / nu (Saffman / Mei lift)
  double shear_ratio = 0.0;  // Re_shear / Re_p = gammadot d_p / |u|, u the closure's velocity (inertial lift)
  double gamma_plus = 0.0;   // dimensionless shear rate gammadot R_c^2 / nu (R_c: tube radius)
  double u_r_plus = 0.0;     // dimensionless slip (u_p - u_f) / u_av
  double di = 0.0;           // deformation index (L - B) / (L + B) of the RBC
  double hematocrit = 0.0;   // local RBC volume fraction (solid fraction phi)
};
using DragInputs = ClosureInputs;
using LiftInputs = ClosureInputs;
using DeformationInputs = ClosureInputs;

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  [[nodiscard]] bool contains(double v) const { return v >= lo && v <= hi; }
};

struct InputVariable {
  std::string_view name;             // as written in closure files and expressions
  double ClosureInputs::*field;
  std::string_view definition;
};

/// The single list of closure input names; a closure file may use no other.
inline constexpr std::array<InputVariable, 7> input_variables{{
    {"re_p", &ClosureInputs::re_p, "particle Reynolds number d_p |u_p - u_f| / nu"},
    {"re_shear", &ClosureInputs::re_shear, "shear Reynolds number gammadot d_p^2 / nu"},
    {"shear_ratio", &ClosureInputs::shear_ratio, "shear to velocity ratio Re_shear / Re_p = gammadot d_p / |u|"},
    {"gamma_plus", &ClosureInputs::gamma_plus, "dimensionless shear rate gammadot R_c^2 / nu"},
    {"u_r_plus", &ClosureInputs::u_r_plus, "dimensionless slip velocity (u_p - u_f) / u_av"},
    {"di", &ClosureInputs::di, "deformation index (L - B) / (L + B) of the red blood cell"},
    {"hematocrit", &ClosureInputs::hematocrit, "local red-blood-cell volume fraction"},
}};

[[nodiscard]] inline std::optional<InputVariable> find_input(std::string_view name) {
  for (const auto& v : input_variables) {
    if (v.name == name) return v;
  }
  return std::nullopt;
}

}  // namespace hs::closures
