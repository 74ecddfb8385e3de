// SPDX-License-Identifier: MIT
// Units parse to SI dimensions, dimensional analysis accepts exactly the consistent formulas (constants are
// wildcards, as PySR's), and a search told the units keeps every formula it records consistent.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "regression/data_view.hpp"
#include "regression/dimension.hpp"
#include "regression/infix.hpp"
#include "regression/symbolic_regressor.hpp"

namespace hsr = hs::regression;

namespace {

const std::vector<std::string> kNames{"d", "t", "mu"};   // a length, a time, a viscosity

std::vector<hsr::Dimension> dims() { return {hsr::parse_unit("m"), hsr::parse_unit("s"), hsr::parse_unit("Pa*s")}; }

bool consistent(const std::string& formula) {
  return hsr::check_dimensions(hsr::parse_infix(formula, kNames), dims()).consistent;
}

}  // namespace

TEST(Dimension, DerivedUnitsAreTheirBaseUnits) {
  EXPECT_EQ(hsr::parse_unit("N"), hsr::parse_unit("kg*m/s^2"));
  EXPECT_EQ(hsr::parse_unit("Pa*s"), hsr::parse_unit("kg / m / s"));
  EXPECT_EQ(hsr::parse_unit("J"), hsr::parse_unit("N*m"));
  EXPECT_TRUE(hsr::parse_unit("1").dimensionless());
  EXPECT_TRUE(hsr::parse_unit("m/m").dimensionless());
  EXPECT_EQ(hsr::unit_text(hsr::parse_unit("Pa")), "kg*m^-1*s^-2");
  EXPECT_EQ(hsr::unit_text(hsr::parse_unit("m^-1")), "m^-1");
  EXPECT_THROW((void)hsr::parse_unit("um"), std::invalid_argument);   // SI only: a micrometre column is not SI
  EXPECT_THROW((void)hsr::parse_unit("m*"), std::invalid_argument);
  EXPECT_THROW((void)hsr::parse_unit(""), std::invalid_argument);
}

TEST(Dimension, OnlyConsistentFormulasPass) {
  EXPECT_TRUE(consistent("d/t"));
  EXPECT_FALSE(consistent("d + t"));                 // a length plus a time
  EXPECT_TRUE(consistent("d + 2.5*t"));              // the constant takes m/s
  EXPECT_FALSE(consistent("exp(d)"));                // exp of a length
  EXPECT_TRUE(consistent("exp(d/(3*t)*t/d)"));       // dimensionless argument
  EXPECT_FALSE(consistent("sin(mu)"));
  EXPECT_TRUE(consistent("sin(1.3*mu)"));            // a wildcard constant makes any argument consistent (PySR)
  EXPECT_FALSE(consistent("d^t"));                   // a dimensional base to a dimensional power
  EXPECT_FALSE(consistent("sqrt(d) + d"));
  const auto sqrt_area = hsr::check_dimensions(hsr::parse_infix("sqrt(d*d)", kNames), dims());
  ASSERT_TRUE(sqrt_area.consistent && sqrt_area.dimension);
  EXPECT_EQ(*sqrt_area.dimension, hsr::parse_unit("m"));
  const auto stokes = hsr::parse_infix("3*3.14159*mu*d*(d/t)", kNames);   // 3 pi mu d U: a force
  EXPECT_TRUE(hsr::dimensionally_consistent(stokes, dims(), hsr::parse_unit("N")));
  EXPECT_FALSE(hsr::dimensionally_consistent(hsr::parse_infix("mu*d*d", kNames), dims(), hsr::parse_unit("N")));
}

// y = d/t + 0.3 sin(d) on data: the unconstrained search uses sin(d) freely; told the units, every program it
// records (the front and the best) must pass the analysis, whatever its loss.
TEST(Dimension, AConstrainedSearchRecordsOnlyConsistentFormulas) {
  std::mt19937_64 rng(3);
  std::vector<std::vector<double>> x(3, std::vector<double>(200));
  std::vector<double> y(200);
  for (std::size_t i = 0; i < y.size(); ++i) {
    for (auto& col : x) col[i] = std::uniform_real_distribution<double>(0.5, 2.0)(rng);
    y[i] = x[0][i] / x[1][i] + 0.3 * std::sin(x[0][i]);
  }
  hsr::SearchSettings s = hsr::full_engine_defaults();
  s.population_size = 300;
  s.generations = 8;
  s.seed = 11;
  s.functions = {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Sin, hsr::Op::Exp};
  s.feature_dimensions = dims();
  s.target_dimension = hsr::parse_unit("m/s");
  const hsr::ColumnData data(x);
  const auto result = hsr::SymbolicRegressor(s).fit(data.view(), y);
  ASSERT_FALSE(result.front.empty());
  for (const auto& entry : result.front) {
    EXPECT_TRUE(hsr::check_dimensions(entry.expression, dims()).consistent) << hsr::to_infix(entry.expression, kNames);
  }
  EXPECT_TRUE(hsr::check_dimensions(result.best, dims()).consistent) << hsr::to_infix(result.best, kNames);
  // The same search without units records sin(d) somewhere: the constraint, not luck, kept it out above.
  s.feature_dimensions.clear();
  s.target_dimension.reset();
  const auto free_result = hsr::SymbolicRegressor(s).fit(data.view(), y);
  bool any_inconsistent = false;
  for (const auto& entry : free_result.front) any_inconsistent |= !hsr::check_dimensions(entry.expression, dims()).consistent;
  EXPECT_TRUE(any_inconsistent);
}
