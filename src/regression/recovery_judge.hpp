// SPDX-License-Identifier: MIT
// Whether a search recovered a ground-truth equation: the same formula, not merely a good fit.
#pragma once

#include <string>
#include <vector>

#include "regression/expression.hpp"
#include "regression/feynman_table.hpp"

namespace hs::regression {

/// Relative tolerance on each constant of the canonical forms. Noise-free data: the constant optimiser reaches
/// ~1e-10, so 1e-6 only absorbs round-off. Noisy data: a constant fitted on 400 rows with noise 0.01 std(y) is off
/// by ~5e-4 of its value, so it is compared at 1e-3, the tolerance PhySO's Feynman benchmark rounds constants with
/// (Tenachi et al. 2023); SRBench (La Cava et al. 2021) likewise judges noisy runs symbolically after rounding.
[[nodiscard]] double constant_tolerance(double noise_level);

/// Symbolic equivalence: both expressions are put in canonical form (algebraic simplification, polynomial
/// expansion, constants within `tolerance` of a short fraction snapped to it) and must be equal node by node,
/// every remaining constant within
/// `tolerance` (relative) of its counterpart; or else their sum-of-products normal forms (normal_form.hpp: operand
/// order, grouping, division and roots taken out) must be equal, every number within `tolerance`. With `srbench_slack`, SRBench's rule ("y - y_hat = a or
/// y / y_hat = b"): one additive or one multiplicative constant at the root of each may differ freely, so
/// 0.52 k x^2 counts as 1/2 k x^2 (the rule the SRBench rates of issue #29 were measured with).
[[nodiscard]] bool same_form(const Expression& model, const Expression& truth, double tolerance, bool srbench_slack);

struct RecoveryVerdict {
  std::string expression;     // the model, infix, in the table's variable names
  double r2_test = 0.0;       // on 1000 fresh noise-free points
  double max_rel_error = 0.0; // max |model - truth| / |truth| on those points
  bool symbolic = false;      // same_form at constant_tolerance(noise), SRBench's slack allowed
  bool strict = false;        // same_form at constant_tolerance(noise), every constant counted
  bool numeric = false;       // noise-free only: the same variables and max_rel_error <= 1e-4 (identities the
                              // simplifier does not know, e.g. sin^2 = (1 - cos 2x)/2)
  bool exact = false;         // symbolic || numeric: SRBench's "symbolic solution"
  bool exact_strict = false;  // strict || numeric
};

/// The judge's rules change (2: the normal form added); a verdict archived by an older one is judged again.
inline constexpr int kRecoveryJudgeVersion = 2;

/// Judges `model`, found on data with Gaussian noise of `noise_level` std(y), against the table's equation.
[[nodiscard]] RecoveryVerdict judge_recovery(const FeynmanEquation& eq, const Expression& model, double noise_level);

}  // namespace hs::regression
