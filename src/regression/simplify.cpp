// SPDX-License-Identifier: MIT
// Rule-based bottom-up simplification of prefix expressions.
#include "regression/simplify.hpp"

#include <array>
#include <cmath>

namespace hs::regression {
namespace {

bool is_const(const Expression& e) { return e.size() == 1 && e[0].op == Op::Const; }
bool is_value(const Expression& e, double v) { return is_const(e) && e[0].value == v; }

Expression leaf(double v) { return Expression({Node::constant(v)}); }

Expression make(Op op, const Expression& a, const Expression& b = {}) {
  std::vector<Node> n{Node::function(op)};
  n.insert(n.end(), a.nodes().begin(), a.nodes().end());
  n.insert(n.end(), b.nodes().begin(), b.nodes().end());
  return Expression(std::move(n));
}

// Children of a function node at the root of `e`.
Expression first_child(const Expression& e) { return e.subtree(1); }
Expression second_child(const Expression& e) { return e.subtree(e.subtree_end(1)); }

Expression rewrite_add(const Expression& a, const Expression& b) {
  if (is_value(a, 0.0)) return b;
  if (is_value(b, 0.0)) return a;
  if (is_const(b)) return make(Op::Add, b, a);
  if (b[0].op == Op::Neg) return make(Op::Sub, a, first_child(b));
  if (b[0].op == Op::Mul && is_const(first_child(b)) && first_child(b)[0].value < 0.0) {   // a + (-c)*x -> a - c*x
    return make(Op::Sub, a, make(Op::Mul, leaf(-first_child(b)[0].value), second_child(b)));
  }
  if (is_const(a) && b[0].op == Op::Add && is_const(first_child(b))) {
    return make(Op::Add, leaf(a[0].value + first_child(b)[0].value), second_child(b));
  }
  return make(Op::Add, a, b);
}

Expression rewrite_sub(const Expression& a, const Expression& b, bool algebraic) {
  if (is_value(b, 0.0)) return a;
  if (is_value(a, 0.0)) return make(Op::Neg, b);
  if (a == b) return leaf(0.0);
  if (is_const(b)) return make(Op::Add, leaf(-b[0].value), a);
  if (b[0].op == Op::Neg) return make(Op::Add, a, first_child(b));
  if (algebraic && b[0].op == Op::Add) return make(Op::Sub, make(Op::Sub, a, first_child(b)), second_child(b));
  return make(Op::Sub, a, b);
}

// A term that already carries a constant factor: c, c*x or c/x.
bool is_scaled(const Expression& e) {
  return is_const(e) || ((e[0].op == Op::Mul || e[0].op == Op::Div) && is_const(first_child(e)));
}

// Algebraic: c * (c1 / x) -> (c c1) / x, and c * (a + b) -> c a + c b when both terms carry a constant.
Expression rewrite_mul_algebraic(const Expression& a, const Expression& b) {
  if (b[0].op == Op::Div && is_const(first_child(b))) {
    return make(Op::Div, leaf(a[0].value * first_child(b)[0].value), second_child(b));
  }
  if ((b[0].op == Op::Add || b[0].op == Op::Sub) && is_scaled(first_child(b)) && is_scaled(second_child(b))) {
    return make(b[0].op, make(Op::Mul, a, first_child(b)), make(Op::Mul, a, second_child(b)));
  }
  return make(Op::Mul, a, b);
}

Expression rewrite_mul(const Expression& a, const Expression& b, bool algebraic) {
  if (is_value(a, 0.0) || is_value(b, 0.0)) return leaf(0.0);
  if (is_value(a, 1.0)) return b;
  if (is_value(b, 1.0)) return a;
  if (is_const(b)) return make(Op::Mul, b, a);
  if (is_value(a, -1.0)) return make(Op::Neg, b);
  if (is_const(a) && b[0].op == Op::Mul && is_const(first_child(b))) {
    return make(Op::Mul, leaf(a[0].value * first_child(b)[0].value), second_child(b));
  }
  if (algebraic && is_const(a)) return rewrite_mul_algebraic(a, b);
  return make(Op::Mul, a, b);
}

// True-division rules (Algebraic mode): constants move out of quotients to the front of the product.
Expression rewrite_div_algebraic(const Expression& a, const Expression& b) {
  const bool a_scaled = a[0].op == Op::Mul && is_const(first_child(a));
  const bool b_scaled = b[0].op == Op::Mul && is_const(first_child(b));
  const Expression num = a_scaled ? second_child(a) : a;
  const Expression den = b_scaled ? second_child(b) : b;
  const double c = (a_scaled ? first_child(a)[0].value : 1.0) / (b_scaled ? first_child(b)[0].value : 1.0);
  return make(Op::Mul, leaf(c), make(Op::Div, num, den));
}

Expression rewrite_div(const Expression& a, const Expression& b, bool algebraic) {
  if (is_value(b, 1.0)) return a;
  // Algebraic: a / (c + k x) -> (1/k) * (a / (c/k + x)): the variable part of a denominator gets coefficient 1.
  if (algebraic && b[0].op == Op::Add && is_const(first_child(b)) && second_child(b)[0].op == Op::Mul &&
      is_const(second_child(b).subtree(1)) && std::abs(second_child(b).subtree(1)[0].value) > 0.0) {
    const double k = second_child(b).subtree(1)[0].value;
    const Expression x = second_child(b).subtree(second_child(b).subtree_end(1));
    return make(Op::Mul, leaf(1.0 / k), make(Op::Div, a, make(Op::Add, leaf(first_child(b)[0].value / k), x)));
  }
  if (algebraic && !is_const(b) && ((a[0].op == Op::Mul && is_const(first_child(a))) ||
                                    (b[0].op == Op::Mul && is_const(first_child(b))))) {
    return rewrite_div_algebraic(a, b);
  }
  if (a == b) return leaf(1.0);   // protected: x / x is 1 also where |x| <= 0.001
  if (is_const(b) && std::abs(b[0].value) > protect_threshold) return make(Op::Mul, leaf(1.0 / b[0].value), a);
  return make(Op::Div, a, b);
}

Expression rewrite(Op op, const Expression& a, const Expression& b, bool algebraic) {
  if (is_const(a) && (arity(op) == 1 || is_const(b))) {
    return leaf(apply(op, a[0].value, arity(op) == 2 ? b[0].value : 0.0));
  }
  switch (op) {
    case Op::Add: return rewrite_add(a, b);
    case Op::Sub: return rewrite_sub(a, b, algebraic);
    case Op::Mul: return rewrite_mul(a, b, algebraic);
    case Op::Div: return rewrite_div(a, b, algebraic);
    case Op::Exp:   // Algebraic: exp(log a) = |a| where |a| > 0.001
      if (algebraic && a[0].op == Op::Log) return make(Op::Abs, first_child(a));
      return make(op, a);
    case Op::Log:   // Algebraic: log(exp a) = a for -6.9 < a <= 230
      if (algebraic && a[0].op == Op::Exp) return first_child(a);
      return make(op, a);
    case Op::Sqrt:
      if (algebraic && a[0].op == Op::Mul && first_child(a) == second_child(a)) return make(Op::Abs, first_child(a));   // Algebraic: sqrt(c * x) = sqrt(c) * sqrt(x) for c > 0 (protected sqrt uses |.| anyway)
      if (algebraic && a[0].op == Op::Mul && is_const(first_child(a))) {
        return make(Op::Mul, leaf(std::sqrt(std::abs(first_child(a)[0].value))), make(Op::Sqrt, second_child(a)));
      }
      return make(op, a);
    case Op::Neg:
      if (a[0].op == Op::Neg) return first_child(a);
      return make(op, a);
    case Op::Pow:
      if (is_value(b, 1.0)) return make(Op::Abs, a);   // protected pow uses |a|
      if (is_value(b, 0.0)) return leaf(1.0);
      return make(op, a, b);
    default: return arity(op) == 2 ? make(op, a, b) : make(op, a);
  }
}

Expression simplify_once(const Expression& e, std::size_t i, bool algebraic) {
  const Node& n = e[i];
  if (n.is_terminal()) return Expression({n});
  const Expression a = simplify_once(e, i + 1, algebraic);
  const Expression b = arity(n.op) == 2 ? simplify_once(e, e.subtree_end(i + 1), algebraic) : Expression{};
  return rewrite(n.op, a, b, algebraic);
}

}  // namespace

Expression simplify(const Expression& e, SimplifyMode mode) {
  const bool algebraic = mode == SimplifyMode::Algebraic;
  if (e.empty()) return e;
  Expression current = e;
  for (int pass = 0; pass < 16; ++pass) {
    Expression next = simplify_once(current, 0, algebraic);
    if (next == current) break;
    current = std::move(next);
  }
  return current;
}

Expression snap_constants(const Expression& e, double tolerance) {
  constexpr std::array<double, 8> denominators{1.0, 2.0, 4.0, 8.0, 10.0, 16.0, 100.0, 1000.0};
  Expression out = e;
  for (Node& n : out.nodes()) {
    if (n.op != Op::Const) continue;
    for (double d : denominators) {
      const double snapped = std::round(n.value * d) / d;
      if (std::abs(snapped - n.value) <= tolerance * std::max(std::abs(n.value), 1e-300)) {
        n.value = snapped;
        break;
      }
    }
  }
  return out;
}

}  // namespace hs::regression
