// SPDX-License-Identifier: MIT
// The recovery judge says "the same formula" for equal forms (up to SRBench's additive or multiplicative constant
// and the tolerance on constants) and "not the same" for anything else, however good its fit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "regression/infix.hpp"
#include "regression/op.hpp"
#include "regression/recovery_judge.hpp"

namespace hsr = hs::regression;

namespace {

const std::vector<std::string> kNames{"k", "x", "y"};

hsr::Expression parse(const std::string& text) { return hsr::parse_infix(text, kNames); }

}  // namespace

TEST(RecoveryJudge, ConstantsCountWithinTheirTolerance) {
  const auto truth = parse("1/2*k*x^2");
  EXPECT_TRUE(hsr::same_form(parse("0.5*(k*(x*x))"), truth, 1e-6, false));
  // 0.5004 is 8e-4 off: a noisy fit's constant (tolerance 1e-3), not a noise-free one's (1e-6).
  EXPECT_TRUE(hsr::same_form(parse("0.5004*k*x^2"), truth, hsr::constant_tolerance(0.01), false));
  EXPECT_FALSE(hsr::same_form(parse("0.5004*k*x^2"), truth, hsr::constant_tolerance(0.0), false));
  EXPECT_FALSE(hsr::same_form(parse("0.52*k*x^2"), truth, hsr::constant_tolerance(0.01), false));
  EXPECT_FALSE(hsr::same_form(parse("k*x^2 + 0.5*x"), parse("k*x^2 + 0.6*x"), hsr::constant_tolerance(0.01), true));
}

TEST(RecoveryJudge, SrbenchAllowsOneOffsetOrOneFactor) {
  const auto truth = parse("k*x/y");
  EXPECT_TRUE(hsr::same_form(parse("k*x/y + 0.37"), truth, 1e-6, true));    // y - y_hat = a
  EXPECT_TRUE(hsr::same_form(parse("2.5*(k*x/y)"), truth, 1e-6, true));     // y / y_hat = b
  EXPECT_FALSE(hsr::same_form(parse("2.5*(k*x/y)"), truth, 1e-6, false));   // not without the slack
  EXPECT_TRUE(hsr::same_form(parse("0.52*k*x^2"), parse("1/2*k*x^2"), 1e-6, true));
  // A noisy fit's intercept and a slope within 1e-3 of 1 (I.12.5 at noise 0.01): the slope snaps to 1, the
  // intercept is SRBench's offset.
  EXPECT_TRUE(hsr::same_form(parse("-0.0058 + 1.0006*(k*x/y)"), truth, hsr::constant_tolerance(0.01), true));
  EXPECT_FALSE(hsr::same_form(parse("-0.0058 + 1.0006*(k*x/y)"), truth, hsr::constant_tolerance(0.0), true));
  EXPECT_FALSE(hsr::same_form(parse("k*x/y + x"), truth, 1e-6, true));      // an extra variable term: another formula
  EXPECT_FALSE(hsr::same_form(parse("k*y/x"), truth, 1e-6, true));
  EXPECT_FALSE(hsr::same_form(parse("k*x"), truth, 1e-6, true));
}

TEST(RecoveryJudge, ProtectedArcsineNeverGivesNan) {
  // asin is clamped to [-1, 1] like the other protected functions, so a GP program with it stays finite.
  EXPECT_DOUBLE_EQ(hsr::apply(hsr::Op::Asin, 0.5, 0.0), std::asin(0.5));
  EXPECT_DOUBLE_EQ(hsr::apply(hsr::Op::Asin, 3.0, 0.0), std::asin(1.0));
  EXPECT_DOUBLE_EQ(hsr::apply(hsr::Op::Asin, -7.0, 0.0), std::asin(-1.0));
  EXPECT_EQ(hsr::op_from_name("asin"), hsr::Op::Asin);
}

namespace {

const std::vector<std::string> kFeynmanNames{"x1", "x2", "x3", "y1", "y2", "y3", "n", "d", "lambd", "V", "kb", "T",
                                             "pr", "gamma", "rho", "q1", "r", "epsilon"};

hsr::Expression feynman(const std::string& text) { return hsr::parse_infix(text, kFeynmanNames); }

}  // namespace

TEST(RecoveryJudge, OperandOrderGroupingAndDivisionDoNotHideTheFormula) {
  // Forms the search printed in the noise-0.01 run of 2026-12-02 (bench/results/2026-12-02_feynman.runs.jsonl)
  // that the simplifier's canonical form did not match: the same formulas, other operand orders and groupings.
  const double noisy = hsr::constant_tolerance(0.01);
  const auto i11_19 = feynman("x1*y1+x2*y2+x3*y3");
  EXPECT_TRUE(hsr::same_form(feynman("x3*y3 + y2*x2 + y1*x1"), i11_19, 1e-6, false));
  EXPECT_TRUE(hsr::same_form(feynman("-0.002566 + 1.0000725*(x3*y3 + y2*x2 + y1*x1)"), i11_19, noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("-0.002566 + 1.0000725*(x3*y3 + y2*x2 + y1*x1)"), i11_19, noisy, false));
  EXPECT_TRUE(hsr::same_form(feynman("asin(lambd/n/d)"), feynman("asin(lambd/(n*d))"), 1e-6, false));        // I.30.5
  EXPECT_TRUE(hsr::same_form(feynman("n/(V/kb/T)"), feynman("n*kb*T/V"), 1e-6, false));                      // I.39.22
  EXPECT_TRUE(hsr::same_form(feynman("sqrt(pr*(gamma/rho))"), feynman("sqrt(gamma*pr/rho)"), 1e-6, false));  // I.47.23
  // I.12.4: 1/(4 pi) = 0.0795775 fitted as 0.0795467 (3.9e-4 off: inside the noisy tolerance, not the noise-free one).
  const auto i12_4 = feynman("q1*r/(4*3.141592653589793*epsilon*r^3)");
  EXPECT_TRUE(hsr::same_form(feynman("0.07954671729541195*(q1/r/epsilon/r)"), i12_4, noisy, false));
  EXPECT_FALSE(hsr::same_form(feynman("0.07954671729541195*(q1/r/epsilon/r)"), i12_4, 1e-6, false));
}

TEST(RecoveryJudge, TheNormalFormStillTellsOtherFormulasApart) {
  // Negative controls for the normal form: a term missing, a divisor moved into the numerator, a root over
  // part of a product, a power off by one, a constant off by 1 %, each a different function.
  const double noisy = hsr::constant_tolerance(0.01);
  EXPECT_FALSE(hsr::same_form(feynman("x1*y1 + x2*y2"), feynman("x1*y1+x2*y2+x3*y3"), noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("asin(lambd/n*d)"), feynman("asin(lambd/(n*d))"), noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("sqrt(pr*gamma)/rho"), feynman("sqrt(gamma*pr/rho)"), noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("q1/r/epsilon"), feynman("q1*r/(epsilon*r^3)"), noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("x1*y1 + 1.01*x2*y2"), feynman("x1*y1+x2*y2"), noisy, true));
  EXPECT_FALSE(hsr::same_form(feynman("x1*y1 - x2*y2"), feynman("x1*y1+x2*y2"), noisy, true));
}
