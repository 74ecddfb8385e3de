// SPDX-License-Identifier: MIT
// The primitive operations of an expression and their protected (never NaN/inf) scalar semantics.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace hs::regression {

/// Every node kind an expression may hold. Const and Var are terminals; the rest are functions.
enum class Op : int {   // int, not uint8_t: GCC 12 gives false -Wstringop-overflow on byte-enum vectors
  Const, Var,
  Add, Sub, Mul, Div, Pow, Min, Max,                        // binary
  Sqrt, Log, Exp, Neg, Inv, Abs, Sin, Cos, Tanh, Asin,      // unary
};

/// gplearn functions.py: div, log and inv are "protected" below this magnitude of their argument.
inline constexpr double protect_threshold = 0.001;
/// exp and pow saturate here (about e^230) so that no function maps a finite argument to inf.
inline constexpr double saturation = 1e100;
inline constexpr double exp_argument_cap = 230.0;   // exp(230) ~ 7.7e99 < saturation

[[nodiscard]] int arity(Op op);
[[nodiscard]] std::string_view op_name(Op op);
/// The function named `name` in a function-set list or an infix call ("add", "sqrt", ...); nullopt if none.
[[nodiscard]] std::optional<Op> op_from_name(std::string_view name);
/// All function ops, in enum order (the "all" function set).
[[nodiscard]] std::vector<Op> all_functions();

/// Protected division (gplearn): a / b, or 1 where |b| <= 0.001.
[[nodiscard]] inline double protected_div(double a, double b) {
  return std::abs(b) > protect_threshold ? a / b : 1.0;
}
/// Protected power: |a|^b, 0 where |a| <= 0.001 and b < 0, saturated at 1e100.
[[nodiscard]] inline double protected_pow(double a, double b) {
  const double base = std::abs(a);
  if (base <= protect_threshold && b < 0.0) return 0.0;
  const double r = std::pow(base, b);
  return r < saturation ? r : saturation;
}
[[nodiscard]] inline double protected_log(double x) {
  return std::abs(x) > protect_threshold ? std::log(std::abs(x)) : 0.0;
}
[[nodiscard]] inline double protected_inv(double x) { return std::abs(x) > protect_threshold ? 1.0 / x : 0.0; }
[[nodiscard]] inline double protected_exp(double x) { return std::exp(std::min(x, exp_argument_cap)); }
[[nodiscard]] inline double protected_sqrt(double x) { return std::sqrt(std::abs(x)); }
/// arcsin of the argument clamped to [-1, 1] (the edge value outside), so that no finite argument gives NaN.
[[nodiscard]] inline double protected_asin(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }

/// The protected scalar semantics of a function op (b is ignored for unary ops).
[[nodiscard]] inline double apply(Op op, double a, double b) {
  switch (op) {
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return protected_div(a, b);
    case Op::Pow: return protected_pow(a, b);
    case Op::Min: return std::min(a, b);
    case Op::Max: return std::max(a, b);
    case Op::Sqrt: return protected_sqrt(a);
    case Op::Log: return protected_log(a);
    case Op::Exp: return protected_exp(a);
    case Op::Neg: return -a;
    case Op::Inv: return protected_inv(a);
    case Op::Abs: return std::abs(a);
    case Op::Sin: return std::sin(a);
    case Op::Cos: return std::cos(a);
    case Op::Tanh: return std::tanh(a);
    case Op::Asin: return protected_asin(a);
    case Op::Const:
    case Op::Var: break;
  }
  return 0.0;
}

}  // namespace hs::regression
