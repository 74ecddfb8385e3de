// SPDX-License-Identifier: MIT
// The recovery judge: canonical forms compared with a tolerance on constants, and the noise-free numeric rule.
#include "regression/recovery_judge.hpp"

#include <algorithm>
#include <cmath>

#include "regression/compiled_program.hpp"
#include "regression/data_view.hpp"
#include "regression/infix.hpp"
#include "regression/metrics.hpp"
#include "regression/normal_form.hpp"
#include "regression/polynomial.hpp"
#include "regression/simplify.hpp"

namespace hs::regression {
namespace {

/// Simplified, expanded, constants within `tolerance` of a short fraction snapped to it (a noisy fit's 1.0006
/// becomes 1, as PhySO rounds to the nearest integer within 0.001), simplified again (the 1 disappears).
Expression canonical(const Expression& e, double tolerance) {
  constexpr auto mode = SimplifyMode::Algebraic;
  return simplify(snap_constants(expand_polynomials(simplify(e, mode)), tolerance), mode);
}

bool is_const(const Expression& e, std::size_t i) { return e[i].op == Op::Const; }

/// The root's non-constant operand when the root combines a constant with it by `ops` (Add/Sub for an offset,
/// Mul/Div for a factor; a constant divisor only, c / f is not a factor); the expression itself otherwise.
Expression without_root_constant(const Expression& e, bool additive) {
  if (e.empty() || arity(e[0].op) != 2) return e;
  const std::size_t a = 1, b = e.subtree_end(1);
  const Op op = e[0].op;
  const bool matches = additive ? (op == Op::Add || op == Op::Sub) : (op == Op::Mul || op == Op::Div);
  if (!matches) return e;
  if (is_const(e, b)) return e.subtree(a);
  if (is_const(e, a) && op != Op::Div && op != Op::Sub) return e.subtree(b);
  return e;
}

bool equal_within(const Expression& a, const Expression& b, double tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].op != b[i].op) return false;
    if (a[i].op == Op::Var && a[i].var != b[i].var) return false;
    if (a[i].op == Op::Const) {
      const double scale = std::max(std::abs(a[i].value), std::abs(b[i].value));
      if (std::abs(a[i].value - b[i].value) > tolerance * scale) return false;
    }
  }
  return true;
}

}  // namespace

double constant_tolerance(double noise_level) { return noise_level > 0.0 ? 1e-3 : 1e-6; }

bool same_form(const Expression& model, const Expression& truth, double tolerance, bool srbench_slack) {
  const Expression m = canonical(model, tolerance), t = canonical(truth, tolerance);
  if (equal_within(m, t, tolerance)) return true;
  // The sum-of-products normal form: the operand order, grouping, division and roots the simplifier keeps.
  const NormalForm mf = normal_form(model), tf = normal_form(truth);
  if (same_normal_form(mf, tf, tolerance)) return true;
  if (!srbench_slack) return false;
  for (const bool additive : {true, false}) {
    if (equal_within(without_root_constant(m, additive), without_root_constant(t, additive), tolerance)) return true;
    if (same_normal_form(without_root_constant(mf, additive), without_root_constant(tf, additive), tolerance)) return true;
  }
  return false;
}

RecoveryVerdict judge_recovery(const FeynmanEquation& eq, const Expression& model, double noise_level) {
  const FeynmanSample fresh = sample_feynman(eq, 1000, 4242);
  std::vector<double> p(fresh.y.size());
  CompiledProgram(model).evaluate(ColumnData(fresh.x).view(), p);
  RecoveryVerdict v;
  v.expression = to_infix(model, eq.names);
  v.r2_test = r_squared(fresh.y, p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    v.max_rel_error = std::max(v.max_rel_error, std::abs(p[i] - fresh.y[i]) / std::abs(fresh.y[i]));
  }
  v.symbolic = same_form(model, eq.truth, constant_tolerance(noise_level), true);
  v.strict = same_form(model, eq.truth, constant_tolerance(noise_level), false);
  v.numeric = noise_level == 0.0 && model.variables() == eq.truth.variables() && v.max_rel_error <= 1e-4;
  v.exact = v.symbolic || v.numeric;
  v.exact_strict = v.strict || v.numeric;
  return v;
}

}  // namespace hs::regression
