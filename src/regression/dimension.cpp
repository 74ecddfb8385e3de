// SPDX-License-Identifier: MIT
// Unit parsing and the dimensional analysis of an expression tree.
#include "regression/dimension.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace hs::regression {
namespace {

constexpr std::array<std::string_view, 7> kBase{"kg", "m", "s", "A", "K", "mol", "cd"};

Dimension of(std::initializer_list<double> e) {
  Dimension d;
  std::size_t i = 0;
  for (double v : e) d.exponent[i++] = v;
  return d;
}

const std::map<std::string, Dimension, std::less<>>& named_units() {
  //                                         kg   m   s   A  K mol cd
  static const std::map<std::string, Dimension, std::less<>> units{
      {"kg", of({1, 0, 0})},     {"m", of({0, 1, 0})},       {"s", of({0, 0, 1})},     {"A", of({0, 0, 0, 1})},
      {"K", of({0, 0, 0, 0, 1})}, {"mol", of({0, 0, 0, 0, 0, 1})}, {"cd", of({0, 0, 0, 0, 0, 0, 1})},
      {"N", of({1, 1, -2})},     {"Pa", of({1, -1, -2})},    {"J", of({1, 2, -2})},    {"W", of({1, 2, -3})},
      {"Hz", of({0, 0, -1})},    {"C", of({0, 0, 1, 1})},    {"V", of({1, 2, -3, -1})}, {"rad", of({})},
      {"1", of({})}};
  return units;
}

bool same(double a, double b) { return std::abs(a - b) < 1e-9; }

/// Unifies two operand dimensions that must agree (a wildcard takes the other's).
DimensionCheck agree(const DimensionCheck& a, const DimensionCheck& b) {
  if (!a.consistent || !b.consistent) return {false, {}};
  if (!a.dimension) return b;
  if (!b.dimension) return a;
  return *a.dimension == *b.dimension ? a : DimensionCheck{false, {}};
}

/// A function of a dimensionless argument (exp, log, sin, ...): its result is dimensionless.
DimensionCheck dimensionless_argument(const DimensionCheck& a) {
  if (!a.consistent || (a.dimension && !a.dimension->dimensionless())) return {false, {}};
  return {true, Dimension{}};
}

DimensionCheck walk(const Expression& e, std::size_t i, const std::vector<Dimension>& vars) {
  const Node& n = e[i];
  if (n.op == Op::Const) return {true, std::nullopt};
  if (n.op == Op::Var) {
    if (n.var >= vars.size()) throw std::invalid_argument(fmt::format("no dimension for feature {}", n.var));
    return {true, vars[n.var]};
  }
  const DimensionCheck a = walk(e, i + 1, vars);
  if (arity(n.op) == 1) {
    switch (n.op) {
      case Op::Neg:
      case Op::Abs: return a;
      case Op::Sqrt: return a.dimension ? DimensionCheck{a.consistent, a.dimension->power(0.5)} : a;
      case Op::Inv: return a.dimension ? DimensionCheck{a.consistent, a.dimension->power(-1.0)} : a;
      default: return dimensionless_argument(a);
    }
  }
  const std::size_t second = e.subtree_end(i + 1);
  const DimensionCheck b = walk(e, second, vars);
  if (!a.consistent || !b.consistent) return {false, {}};
  switch (n.op) {
    case Op::Mul:
    case Op::Div: {
      if (!a.dimension || !b.dimension) return {true, std::nullopt};   // scaled by a free constant: free
      return {true, a.dimension->times(*b.dimension, n.op == Op::Mul ? 1.0 : -1.0)};
    }
    case Op::Pow: {
      if (b.dimension && !b.dimension->dimensionless()) return {false, {}};
      if (!a.dimension) return a;
      if (a.dimension->dimensionless()) return a;
      if (e[second].op == Op::Const) return {true, a.dimension->power(e[second].value)};
      return {false, {}};   // a dimensional base to a variable power has no dimension
    }
    default: return agree(a, b);   // add, sub, min, max
  }
}

}  // namespace

bool Dimension::dimensionless() const {
  for (double v : exponent) {
    if (!same(v, 0.0)) return false;
  }
  return true;
}

bool operator==(const Dimension& a, const Dimension& b) {
  for (std::size_t k = 0; k < a.exponent.size(); ++k) {
    if (!same(a.exponent[k], b.exponent[k])) return false;
  }
  return true;
}

Dimension Dimension::times(const Dimension& o, double sign) const {
  Dimension r = *this;
  for (std::size_t k = 0; k < r.exponent.size(); ++k) r.exponent[k] += sign * o.exponent[k];
  return r;
}

Dimension Dimension::power(double p) const {
  Dimension r = *this;
  for (double& v : r.exponent) v *= p;
  return r;
}

Dimension parse_unit(std::string_view text) {
  Dimension d;
  std::size_t i = 0;
  double sign = 1.0;
  bool expect_factor = true;
  auto skip_spaces = [&] { while (i < text.size() && text[i] == ' ') ++i; };
  skip_spaces();
  if (i == text.size()) throw std::invalid_argument("empty unit (write \"1\" for a dimensionless quantity)");
  while (i < text.size()) {
    skip_spaces();
    std::size_t start = i;
    while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) != 0)) ++i;
    const std::string_view name = text.substr(start, i - start);
    const auto it = named_units().find(name);
    if (it == named_units().end()) {
      throw std::invalid_argument(fmt::format("unknown unit \"{}\" in \"{}\" (allowed: SI base units kg m s A K mol "
                                              "cd, derived N Pa J W Hz C V rad, 1, combined with * / ^)", name, text));
    }
    double power = 1.0;
    skip_spaces();
    if (i < text.size() && text[i] == '^') {
      ++i;
      start = i;
      if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
      while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) != 0 || text[i] == '.')) ++i;
      try {
        power = std::stod(std::string(text.substr(start, i - start)));
      } catch (const std::exception&) {
        throw std::invalid_argument(fmt::format("bad exponent in unit \"{}\"", text));
      }
    }
    d = d.times(it->second.power(power), sign);
    expect_factor = false;
    skip_spaces();
    if (i == text.size()) break;
    if (text[i] != '*' && text[i] != '/') throw std::invalid_argument(fmt::format("expected * or / in unit \"{}\"", text));
    sign = text[i] == '*' ? 1.0 : -1.0;
    expect_factor = true;
    ++i;
  }
  if (expect_factor) throw std::invalid_argument(fmt::format("unit \"{}\" ends with an operator", text));
  return d;
}

std::string unit_text(const Dimension& d) {
  std::string out;
  for (std::size_t k = 0; k < kBase.size(); ++k) {
    const double p = d.exponent[k];
    if (same(p, 0.0)) continue;
    if (!out.empty()) out += "*";
    out += same(p, 1.0) ? std::string(kBase[k]) : fmt::format("{}^{}", kBase[k], p);
  }
  return out.empty() ? "1" : out;
}

DimensionCheck check_dimensions(const Expression& e, const std::vector<Dimension>& variables) {
  return walk(e, 0, variables);
}

bool dimensionally_consistent(const Expression& e, const std::vector<Dimension>& variables,
                              const std::optional<Dimension>& target) {
  const DimensionCheck c = check_dimensions(e, variables);
  if (!c.consistent) return false;
  return !target || !c.dimension || *c.dimension == *target;
}

}  // namespace hs::regression
