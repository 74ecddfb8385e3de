// SPDX-License-Identifier: MIT
// Sum-of-products normal form: built bottom-up, each sum and product flattened, like parts merged and sorted.
#include "regression/normal_form.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace hs::regression {
namespace {

using Kind = NormalForm::Kind;

NormalForm make(Kind kind, double value = 0.0, std::vector<NormalForm> parts = {}, std::vector<double> exponents = {}) {
  NormalForm f;
  f.kind = kind;
  f.value = value;
  f.parts = std::move(parts);
  f.exponents = std::move(exponents);
  return f;
}

NormalForm constant(double v) { return make(Kind::Constant, v); }

/// The order of parts: by kind, then variable, function and shape, numbers left out (so that 0.9 x and 1.0 x
/// sort alike on both sides of a comparison within a tolerance); exact numbers only break ties.
std::string shape_key(const NormalForm& f) {
  std::string k(1, static_cast<char>('0' + static_cast<int>(f.kind)));
  if (f.kind == Kind::Variable) k += std::to_string(f.variable);
  if (f.kind == Kind::Call) k += std::to_string(static_cast<int>(f.call));
  k += '(';
  for (const NormalForm& p : f.parts) k += shape_key(p) + ',';
  return k + ')';
}

bool identical(const NormalForm& a, const NormalForm& b) { return same_normal_form(a, b, 0.0); }

bool exact_less(const NormalForm& a, const NormalForm& b) {
  if (a.value != b.value) return a.value < b.value;
  if (a.exponents != b.exponents) return a.exponents < b.exponents;
  const std::size_t n = std::min(a.parts.size(), b.parts.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!identical(a.parts[i], b.parts[i])) return exact_less(a.parts[i], b.parts[i]);
  }
  return a.parts.size() < b.parts.size();
}

bool before(const NormalForm& a, const NormalForm& b) {
  const std::string ka = shape_key(a), kb = shape_key(b);
  return ka != kb ? ka < kb : exact_less(a, b);
}

/// A product's coefficient and powers; anything else is 1 x itself^1 (a constant: its value, no powers).
NormalForm as_product(const NormalForm& f) {
  if (f.kind == Kind::Product) return f;
  if (f.kind == Kind::Constant) return make(Kind::Product, f.value);
  return make(Kind::Product, 1.0, {f}, {1.0});
}

NormalForm add(const NormalForm& a, const NormalForm& b);

/// A product put in order; collapsed to a constant, a lone base, or a sum its coefficient is multiplied into.
NormalForm finish_product(NormalForm p) {
  std::vector<std::pair<NormalForm, double>> powers;
  for (std::size_t i = 0; i < p.parts.size(); ++i) {
    if (p.exponents[i] != 0.0) powers.emplace_back(std::move(p.parts[i]), p.exponents[i]);
  }
  std::sort(powers.begin(), powers.end(), [](const auto& x, const auto& y) { return before(x.first, y.first); });
  p.parts.clear();
  p.exponents.clear();
  for (auto& [base, e] : powers) {
    p.parts.push_back(std::move(base));
    p.exponents.push_back(e);
  }
  if (p.value == 0.0 || p.parts.empty()) return constant(p.value);
  if (p.parts.size() == 1 && p.exponents[0] == 1.0) {
    if (p.value == 1.0) return p.parts[0];
    if (p.parts[0].kind == Kind::Sum) {   // c (t1 + t2) = c t1 + c t2
      NormalForm sum = constant(0.0);
      for (const NormalForm& t : p.parts[0].parts) {
        NormalForm scaled = as_product(t);
        scaled.value *= p.value;
        sum = add(sum, finish_product(scaled));
      }
      return sum;
    }
  }
  return p;
}

NormalForm multiply(const NormalForm& a, const NormalForm& b) {
  NormalForm p = as_product(a);
  const NormalForm q = as_product(b);
  p.value *= q.value;
  for (std::size_t i = 0; i < q.parts.size(); ++i) {
    const auto same = std::find_if(p.parts.begin(), p.parts.end(), [&](const NormalForm& x) { return identical(x, q.parts[i]); });
    if (same != p.parts.end()) {
      p.exponents[static_cast<std::size_t>(same - p.parts.begin())] += q.exponents[i];
    } else {
      p.parts.push_back(q.parts[i]);
      p.exponents.push_back(q.exponents[i]);
    }
  }
  return finish_product(std::move(p));
}

NormalForm power(const NormalForm& a, double e) {
  if (a.kind == Kind::Constant) {   // a number's power as algebra has it (-2)^-1 = -0.5; protected only where undefined
    const double v = std::pow(a.value, e);
    return constant(std::isfinite(v) ? v : apply(Op::Pow, a.value, e));
  }
  NormalForm p = as_product(a);
  // (c x)^e = c^e x^e: a negative coefficient only under an integer power.
  if (p.value < 0.0 && e != std::round(e)) return make(Kind::Product, 1.0, {a}, {e});
  p.value = std::pow(p.value, e);
  for (double& x : p.exponents) x *= e;
  return finish_product(std::move(p));
}

/// A sum's terms; a term's coefficient split off its rest (a constant term: the rest is the constant 1).
std::pair<double, NormalForm> split_term(const NormalForm& t) {
  if (t.kind == Kind::Constant) return {t.value, constant(1.0)};
  NormalForm p = as_product(t);
  const double c = p.value;
  p.value = 1.0;
  return {c, finish_product(std::move(p))};
}

NormalForm add(const NormalForm& a, const NormalForm& b) {
  std::vector<std::pair<double, NormalForm>> terms;
  for (const NormalForm* side : {&a, &b}) {
    const std::vector<NormalForm> list = side->kind == Kind::Sum ? side->parts : std::vector<NormalForm>{*side};
    for (const NormalForm& t : list) {
      auto [c, rest] = split_term(t);
      const auto same = std::find_if(terms.begin(), terms.end(), [&](const auto& x) { return identical(x.second, rest); });
      if (same != terms.end()) {
        same->first += c;
      } else {
        terms.emplace_back(c, std::move(rest));
      }
    }
  }
  NormalForm sum = make(Kind::Sum);
  for (auto& [c, rest] : terms) {
    if (c == 0.0) continue;
    sum.parts.push_back(multiply(constant(c), rest));
  }
  if (sum.parts.empty()) return constant(0.0);
  if (sum.parts.size() == 1) return sum.parts[0];
  std::sort(sum.parts.begin(), sum.parts.end(), before);
  return sum;
}

NormalForm call(Op op, std::vector<NormalForm> args) {
  if (std::all_of(args.begin(), args.end(), [](const NormalForm& x) { return x.kind == Kind::Constant; })) {
    return constant(apply(op, args[0].value, args.size() > 1 ? args[1].value : 0.0));
  }
  if (op == Op::Min || op == Op::Max) std::sort(args.begin(), args.end(), before);
  NormalForm f = make(Kind::Call, 0.0, std::move(args));
  f.call = op;
  return f;
}

NormalForm build(const Expression& e, std::size_t i) {
  const Node& n = e[i];
  if (n.op == Op::Const) return constant(n.value);
  if (n.op == Op::Var) {
    NormalForm f = make(Kind::Variable);
    f.variable = n.var;
    return f;
  }
  const NormalForm a = build(e, i + 1);
  if (arity(n.op) == 1) {
    switch (n.op) {
      case Op::Neg: return multiply(constant(-1.0), a);
      case Op::Inv: return power(a, -1.0);
      case Op::Sqrt: return power(a, 0.5);
      default: return call(n.op, {a});
    }
  }
  const NormalForm b = build(e, e.subtree_end(i + 1));
  switch (n.op) {
    case Op::Add: return add(a, b);
    case Op::Sub: return add(a, multiply(constant(-1.0), b));
    case Op::Mul: return multiply(a, b);
    case Op::Div: return multiply(a, power(b, -1.0));
    case Op::Pow: return b.kind == Kind::Constant ? power(a, b.value) : call(Op::Pow, {a, b});
    default: return call(n.op, {a, b});
  }
}

bool close(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

}  // namespace

NormalForm normal_form(const Expression& e) { return e.empty() ? constant(0.0) : build(e, 0); }

bool same_normal_form(const NormalForm& a, const NormalForm& b, double tolerance) {
  if (a.kind != b.kind || a.parts.size() != b.parts.size()) return false;
  switch (a.kind) {
    case Kind::Constant: return close(a.value, b.value, tolerance);
    case Kind::Variable: return a.variable == b.variable;
    case Kind::Call:
      if (a.call != b.call) return false;
      break;
    case Kind::Product:
      if (!close(a.value, b.value, tolerance)) return false;
      for (std::size_t i = 0; i < a.exponents.size(); ++i) {
        if (!close(a.exponents[i], b.exponents[i], tolerance)) return false;
      }
      break;
    case Kind::Sum: break;
  }
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    if (!same_normal_form(a.parts[i], b.parts[i], tolerance)) return false;
  }
  return true;
}

NormalForm without_root_constant(const NormalForm& f, bool additive) {
  if (additive) {
    if (f.kind != Kind::Sum) return f;
    NormalForm rest = constant(0.0);
    for (const NormalForm& t : f.parts) {
      if (t.kind != Kind::Constant) rest = add(rest, t);
    }
    return rest;
  }
  if (f.kind == Kind::Product) return multiply(constant(1.0 / f.value), f);
  if (f.kind == Kind::Sum) return multiply(constant(1.0 / as_product(f.parts[0]).value), f);
  return f;
}

}  // namespace hs::regression
