// SPDX-License-Identifier: MIT
// Polynomials over the features as monomial -> coefficient maps, and their expansion into expressions.
#include "regression/polynomial.hpp"

#include <cmath>
#include <map>
#include <optional>

namespace hs::regression {
namespace {

using Monomial = std::vector<int>;   // exponent per feature, trailing zeros trimmed
using Poly = std::map<Monomial, double>;

constexpr std::size_t max_terms = 32;   // beyond this, expansion is not a simplification
constexpr int max_degree = 6;

void trim(Monomial& m) {
  while (!m.empty() && m.back() == 0) m.pop_back();
}

Poly add(const Poly& a, const Poly& b, double sign) {
  Poly out = a;
  for (const auto& [m, c] : b) out[m] += sign * c;
  return out;
}

std::optional<Poly> mul(const Poly& a, const Poly& b) {
  Poly out;
  for (const auto& [ma, ca] : a) {
    for (const auto& [mb, cb] : b) {
      Monomial m(std::max(ma.size(), mb.size()), 0);
      int degree = 0;
      for (std::size_t k = 0; k < m.size(); ++k) {
        m[k] = (k < ma.size() ? ma[k] : 0) + (k < mb.size() ? mb[k] : 0);
        degree += m[k];
      }
      if (degree > max_degree) return std::nullopt;
      trim(m);
      out[m] += ca * cb;
    }
  }
  return out;
}

Expression join(Op op, const Expression& a, const Expression& b = {}) {
  std::vector<Node> n{Node::function(op)};
  n.insert(n.end(), a.nodes().begin(), a.nodes().end());
  n.insert(n.end(), b.nodes().begin(), b.nodes().end());
  return Expression(std::move(n));
}

Expression monomial_expression(const Monomial& m, double c) {
  Expression out;
  for (std::size_t k = 0; k < m.size(); ++k) {
    for (int p = 0; p < m[k]; ++p) {
      const Expression v({Node::variable(k)});
      out = out.empty() ? v : join(Op::Mul, out, v);
    }
  }
  if (out.empty()) return Expression({Node::constant(c)});
  if (std::abs(c) == 1.0) return c < 0.0 ? join(Op::Neg, out) : out;
  return join(Op::Mul, Expression({Node::constant(c)}), out);
}

Expression to_expression(const Poly& p) {
  double largest = 0.0;
  for (const auto& [m, c] : p) largest = std::max(largest, std::abs(c));
  Expression out;
  for (const auto& [m, c] : p) {
    if (std::abs(c) <= 1e-12 * largest || c == 0.0) continue;
    if (out.empty()) {
      out = monomial_expression(m, c);
    } else {
      out = c < 0.0 ? join(Op::Sub, out, monomial_expression(m, -c)) : join(Op::Add, out, monomial_expression(m, c));
    }
  }
  return out.empty() ? Expression({Node::constant(0.0)}) : out;
}

struct Walked {
  Expression expr;
  std::optional<Poly> poly;
};

Expression finalize(const Walked& w) {
  if (!w.poly || w.expr.size() <= 1) return w.expr;
  Expression expanded = to_expression(*w.poly);
  return expanded.size() <= w.expr.size() ? expanded : w.expr;
}

std::optional<Poly> combine(Op op, const Walked& a, const Walked& b) {
  if (!a.poly || (arity(op) == 2 && op != Op::Pow && !b.poly)) return std::nullopt;
  switch (op) {
    case Op::Add: return add(*a.poly, *b.poly, 1.0);
    case Op::Sub: return add(*a.poly, *b.poly, -1.0);
    case Op::Mul: return mul(*a.poly, *b.poly);
    case Op::Neg: return add(Poly{}, *a.poly, -1.0);
    case Op::Pow: {
      // protected pow is |a|^k: a polynomial only for even integer k.
      if (b.expr.size() != 1 || b.expr[0].op != Op::Const) return std::nullopt;
      const double k = b.expr[0].value;
      if (k < 0.0 || k > 4.0 || k != std::floor(k) || static_cast<int>(k) % 2 != 0) return std::nullopt;
      std::optional<Poly> r = Poly{{Monomial{}, 1.0}};
      for (int i = 0; i < static_cast<int>(k) && r; ++i) r = mul(*r, *a.poly);
      return r;
    }
    default: return std::nullopt;
  }
}

Walked walk(const Expression& e, std::size_t i) {
  const Node& n = e[i];
  if (n.op == Op::Const) return {Expression({n}), Poly{{Monomial{}, n.value}}};
  if (n.op == Op::Var) {
    Monomial m(static_cast<std::size_t>(n.var) + 1, 0);
    m.back() = 1;
    return {Expression({n}), Poly{{m, 1.0}}};
  }
  const Walked a = walk(e, i + 1);
  const Walked b = arity(n.op) == 2 ? walk(e, e.subtree_end(i + 1)) : Walked{};
  std::optional<Poly> p = combine(n.op, a, b);
  if (p && p->size() <= max_terms) return {join(n.op, a.expr, b.expr), p};
  return {join(n.op, finalize(a), arity(n.op) == 2 ? finalize(b) : Expression{}), std::nullopt};
}

}  // namespace

Expression expand_polynomials(const Expression& e) {
  if (e.empty()) return e;
  return finalize(walk(e, 0));
}

}  // namespace hs::regression
