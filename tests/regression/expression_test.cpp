// SPDX-License-Identifier: MIT
// Expression trees and the infix parser/printer: exact round trips, clear errors.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "regression/genetic_operators.hpp"
#include "regression/infix.hpp"

namespace hsr = hs::regression;

namespace {
const std::vector<std::string> vars{"x", "y", "re_p"};
}

TEST(Infix, ParsesWithPrecedenceAndAssociativity) {
  const double p[3] = {2.0, 3.0, 5.0};
  EXPECT_DOUBLE_EQ(hsr::parse_infix("1 + 2*x^2", vars).evaluate(p), 9.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("x - y - re_p", vars).evaluate(p), -6.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("re_p / y / x", vars).evaluate(p), 5.0 / 3.0 / 2.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("x^y^0.5", vars).evaluate(p), std::pow(2.0, std::sqrt(3.0)));
  EXPECT_DOUBLE_EQ(hsr::parse_infix("-x^2", vars).evaluate(p), -4.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("-2^x", vars).evaluate(p), -4.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("max(x, y) * sqrt(4) + min(1, -x)", vars).evaluate(p), 4.0);
  EXPECT_DOUBLE_EQ(hsr::parse_infix("x/(1 + y)", vars).evaluate(p), 0.5);
}

TEST(Infix, PrintsMinimalParentheses) {
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("(x + y) + re_p", vars), vars), "x + y + re_p");
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("x + (y + re_p)", vars), vars), "x + (y + re_p)");
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("x*(y - 2.5)", vars), vars), "x*(y - 2.5)");
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("2.5*x^2 + x", vars), vars), "2.5*x^2 + x");
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("-(2.5)", vars), vars), "-(2.5)");
  EXPECT_EQ(hsr::to_infix(hsr::parse_infix("(-2.5)^x", vars), vars), "(-2.5)^x");
}

TEST(Infix, MalformedOrUnknownNamesAreParseErrors) {
  EXPECT_THROW((void)hsr::parse_infix("x +", vars), hsr::ParseError);
  EXPECT_THROW((void)hsr::parse_infix("x + (y", vars), hsr::ParseError);
  EXPECT_THROW((void)hsr::parse_infix("x y", vars), hsr::ParseError);
  EXPECT_THROW((void)hsr::parse_infix("foo(x)", vars), hsr::ParseError);
  EXPECT_THROW((void)hsr::parse_infix("min(x)", vars), hsr::ParseError);
  try {
    (void)hsr::parse_infix("x + re_pp", vars);
    FAIL();
  } catch (const hsr::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("re_pp"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("re_p"), std::string::npos) << e.what();
  }
}

TEST(Infix, RandomProgramsRoundTripNodeForNode) {
  hsr::SearchSettings s;
  s.functions = hsr::all_functions();
  s.const_lo = -1e3;
  s.const_hi = 1e3;
  const hsr::GeneticOperators ops(s, vars.size());
  hsr::Rng rng(42);
  for (int i = 0; i < 3000; ++i) {
    hsr::Expression e = ops.random_program(rng);
    if (i % 3 == 0) e = ops.point_mutation(ops.crossover(e, ops.random_program(rng), rng), rng);
    const std::string text = hsr::to_infix(e, vars);
    const hsr::Expression back = hsr::parse_infix(text, vars);
    ASSERT_EQ(back, e) << text;
    ASSERT_EQ(hsr::to_infix(back, vars), text);
  }
}

TEST(Expression, SubtreesDepthAndWellFormedness) {
  const auto e = hsr::parse_infix("x*(y + 1) - sqrt(re_p)", vars);
  EXPECT_EQ(e.size(), 8u);
  EXPECT_EQ(e.depth(), 3);
  EXPECT_TRUE(e.well_formed());
  EXPECT_EQ(e.subtree_end(1), 6u);
  EXPECT_EQ(e.variables(), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_FALSE(hsr::Expression({hsr::Node::function(hsr::Op::Add), hsr::Node::variable(0)}).well_formed());
}
