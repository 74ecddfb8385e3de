// SPDX-License-Identifier: MIT
// The compiled evaluator agrees with the tree, and the protected operators never give NaN or inf.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "regression/compiled_program.hpp"
#include "regression/genetic_operators.hpp"

namespace hsr = hs::regression;

TEST(ProtectedOps, NeverNanOrInfOnExtremeArguments) {
  const std::vector<double> values{0.0, -0.0, 1e-310, -1e-310, 1e-3, -1e-3, 1e-4, -1e-4, 0.5, -0.5, 1.0, -1.0,
                                   3.0, -3.0, 700.0, -700.0, 1e50, -1e50, 1e100, -1e100};
  for (hsr::Op op : hsr::all_functions()) {
    for (double a : values) {
      for (double b : values) {
        const double r = hsr::apply(op, a, b);
        ASSERT_TRUE(std::isfinite(r)) << hsr::op_name(op) << "(" << a << ", " << b << ") = " << r;
      }
    }
  }
  // Unary functions are finite for every finite argument, up to the largest double.
  for (hsr::Op op : hsr::all_functions()) {
    if (hsr::arity(op) != 1) continue;
    for (double a : {DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN}) EXPECT_TRUE(std::isfinite(hsr::apply(op, a, 0.0)));
  }
}

TEST(ProtectedOps, GplearnSemantics) {
  EXPECT_EQ(hsr::protected_div(3.0, 0.0005), 1.0);   // gplearn functions.py: 1 where |x2| <= 0.001
  EXPECT_EQ(hsr::protected_div(3.0, 2.0), 1.5);
  EXPECT_EQ(hsr::protected_log(0.0), 0.0);
  EXPECT_DOUBLE_EQ(hsr::protected_log(-std::exp(1.0)), 1.0);
  EXPECT_EQ(hsr::protected_inv(1e-4), 0.0);
  EXPECT_EQ(hsr::protected_sqrt(-4.0), 2.0);
}

TEST(CompiledProgram, AgreesWithTreeOnRandomProgramsAndBlocks) {
  hsr::SearchSettings s;
  s.functions = hsr::all_functions();
  const hsr::GeneticOperators ops(s, 3);
  hsr::Rng rng(3);
  const std::size_t n = 700;   // spans several blocks and a partial one
  std::vector<std::vector<double>> cols(3, std::vector<double>(n));
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (auto& c : cols) {
    for (double& v : c) v = u(rng);
  }
  const hsr::ColumnData data(cols);
  std::vector<double> out(n);
  for (int k = 0; k < 300; ++k) {
    const auto e = ops.random_program(rng);
    const hsr::CompiledProgram prog(e);
    prog.evaluate(data.view(), out);
    for (std::size_t i = 0; i < n; i += 37) {
      const double point[3] = {cols[0][i], cols[1][i], cols[2][i]};
      const double expect = e.evaluate(point);
      ASSERT_EQ(out[i], expect) << k;   // same operations in the same order: bit-identical
      ASSERT_EQ(prog.evaluate_point(point), expect);
      ASSERT_TRUE(std::isfinite(out[i]));
    }
  }
}

TEST(CompiledProgram, SetConstantsFollowsPrefixOrder) {
  const hsr::Expression e({hsr::Node::function(hsr::Op::Sub), hsr::Node::constant(1.0), hsr::Node::constant(2.0)});
  hsr::CompiledProgram p(e);
  ASSERT_EQ(p.constant_count(), 2u);
  const double c[2] = {10.0, 3.0};
  p.set_constants(c);
  EXPECT_EQ(p.evaluate_point(nullptr), 7.0);
}
