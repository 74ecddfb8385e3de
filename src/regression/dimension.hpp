// SPDX-License-Identifier: MIT
// Physical dimensions of closure inputs and outputs, and whether an expression combines them consistently.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

/// Exponents of the seven SI base units (kg, m, s, A, K, mol, cd); sqrt makes halves, so they are real.
struct Dimension {
  std::array<double, 7> exponent{};

  [[nodiscard]] bool dimensionless() const;
  friend bool operator==(const Dimension& a, const Dimension& b);
  [[nodiscard]] Dimension times(const Dimension& o, double sign = 1.0) const;   // a * o^sign
  [[nodiscard]] Dimension power(double p) const;
};

/// "kg*m/s^2", "Pa*s", "m^-1", "1" (dimensionless); SI base units and the derived ones N, Pa, J, W, Hz, C, V, rad.
/// Throws std::invalid_argument naming the unknown unit or the malformed part (callers add file and key).
[[nodiscard]] Dimension parse_unit(std::string_view text);
/// The canonical text of a dimension ("kg*m^-1*s^-2", "1").
[[nodiscard]] std::string unit_text(const Dimension& d);

/// Dimensional analysis of `e` with feature j of dimension `variables[j]`, as PySR's dimensional constraints:
/// a constant is a wildcard that takes whatever dimension makes its use consistent; + - min max need equal
/// dimensions; exp, log, sin, cos, tanh, asin and a non-constant power need a dimensionless argument.
/// Returns the expression's dimension (nullopt: a wildcard, e.g. a lone constant), or sets `consistent` false.
struct DimensionCheck {
  bool consistent = true;
  std::optional<Dimension> dimension;   // nullopt = free (made of constants, or scaled by one)
};
[[nodiscard]] DimensionCheck check_dimensions(const Expression& e, const std::vector<Dimension>& variables);

/// Consistent and, when `target` is given, of the target's dimension (a free result can take any).
[[nodiscard]] bool dimensionally_consistent(const Expression& e, const std::vector<Dimension>& variables,
                                            const std::optional<Dimension>& target);

}  // namespace hs::regression
