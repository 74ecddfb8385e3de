// SPDX-License-Identifier: MIT
// Simplification keeps the value (protected semantics) and removes what it promises to remove.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "regression/genetic_operators.hpp"
#include "regression/infix.hpp"
#include "regression/simplify.hpp"

namespace hsr = hs::regression;

namespace {
const std::vector<std::string> vars{"x", "y"};
std::string simp(const char* text) { return hsr::to_infix(hsr::simplify(hsr::parse_infix(text, vars)), vars); }
}  // namespace

TEST(Simplify, IdentitiesAndConstantFolding) {
  EXPECT_EQ(simp("x + 0"), "x");
  EXPECT_EQ(simp("1*x*1"), "x");
  EXPECT_EQ(simp("x - x"), "0");
  EXPECT_EQ(simp("(x + y)/(x + y)"), "1");
  EXPECT_EQ(simp("--x"), "x");
  EXPECT_EQ(simp("2*(3*x)"), "6*x");
  EXPECT_EQ(simp("x/2"), "0.5*x");
  EXPECT_EQ(simp("x - 2"), "-2 + x");
  EXPECT_EQ(simp("(1 + 2)*x + sqrt(4)"), "2 + 3*x");
  EXPECT_EQ(simp("x + -y"), "x - y");
}

TEST(Simplify, SnapsNearlyRoundConstants) {
  const auto e = hsr::snap_constants(hsr::parse_infix("2.4999999999997*x + 0.1000000000001", vars));
  EXPECT_EQ(hsr::to_infix(e, vars), "2.5*x + 0.1");
  EXPECT_EQ(hsr::to_infix(hsr::snap_constants(hsr::parse_infix("0.3989422804", vars)), vars), "0.3989422804");
}

TEST(Simplify, KeepsValuesOfRandomPrograms) {
  hsr::SearchSettings s;
  // Without sin/cos/exp/tanh/pow, which can amplify a last-bit change (1/c for /c) beyond any fixed tolerance.
  s.functions = {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Neg, hsr::Op::Sqrt,
                 hsr::Op::Abs, hsr::Op::Min, hsr::Op::Max, hsr::Op::Log, hsr::Op::Inv};
  const hsr::GeneticOperators ops(s, 2);
  hsr::Rng rng(9);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 2000; ++k) {
    const auto e = ops.random_program(rng);
    const auto simple = hsr::simplify(e);
    ASSERT_LE(simple.size(), e.size());
    for (int t = 0; t < 5; ++t) {
      const double p[2] = {u(rng), u(rng)};
      const double a = e.evaluate(p);
      const double b = simple.evaluate(p);
      // Folding 1/c and reassociating constants changes the last bits only: relative 1e-9 with an absolute
      // floor for values that cancel to near zero.
      ASSERT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(a))) << hsr::to_infix(e, vars) << " -> " << hsr::to_infix(simple, vars);
    }
  }
}
