// SPDX-License-Identifier: MIT
// The committed AI-Feynman table reads as published, and the search recovers its easy equations symbolically.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/errors.hpp"
#include "regression/feynman_table.hpp"
#include "regression/infix.hpp"
#include "regression/model_selection.hpp"

namespace hsr = hs::regression;

namespace {

const std::string kTable = std::string(HS_SOURCE_DIR) + "/data/reference/feynman_sr_subset10.csv";

const hsr::FeynmanEquation& find(const std::vector<hsr::FeynmanEquation>& table, const std::string& id) {
  const auto it = std::find_if(table.begin(), table.end(), [&](const auto& eq) { return eq.id == id; });
  if (it == table.end()) throw std::runtime_error("no equation " + id);
  return *it;
}

}  // namespace

TEST(FeynmanTable, ReadsTheTenEquationsWithTheirRanges) {
  const auto table = hsr::read_feynman_table(kTable);
  ASSERT_EQ(table.size(), 10u);
  const auto& distance = find(table, "I.8.14");   // sqrt((x2-x1)**2+(y2-y1)**2), four variables in [1, 5]
  EXPECT_EQ(distance.names, (std::vector<std::string>{"x1", "x2", "y1", "y2"}));
  EXPECT_EQ(distance.lo, std::vector<double>(4, 1.0));
  EXPECT_EQ(distance.hi, std::vector<double>(4, 5.0));
  const double at[4] = {1.0, 4.0, 2.0, 6.0};      // 3-4-5 triangle
  EXPECT_DOUBLE_EQ(distance.truth.evaluate(at), 5.0);
  const auto& gauss = find(table, "I.6.2a");      // exp(-theta**2/2)/sqrt(2*pi): pi read as its value
  const double zero[1] = {0.0};
  EXPECT_NEAR(gauss.truth.evaluate(zero), 0.3989422804014327, 1e-15);
  EXPECT_THROW((void)hsr::read_feynman_table(kTable + ".missing"), hs::common::ConfigError);
}

// The whole AI-Feynman table (data/reference/feynman_ai100.csv): 100 equations, each formula parses with the
// table's own variables (arcsin, ln and pi included) and is finite everywhere on its sampling ranges (a NaN would
// mean a misread range or operator, e.g. sqrt of a negative, and would poison every search on it).
TEST(FeynmanTable, TheFullTableParsesAndIsFiniteOnItsRanges) {
  const auto table = hsr::read_feynman_table(std::string(HS_SOURCE_DIR) + "/data/reference/feynman_ai100.csv");
  ASSERT_EQ(table.size(), 100u);
  for (const auto& eq : table) {
    const auto sample = hsr::sample_feynman(eq, 200, 3);
    for (double y : sample.y) ASSERT_TRUE(std::isfinite(y)) << eq.id << " = " << eq.formula;
  }
  const double snell[2] = {0.5, 1.0};   // I.26.2 arcsin(n*sin(theta2)), n = 0.5, theta2 = 1
  EXPECT_NEAR(find(table, "I.26.2").truth.evaluate(snell), std::asin(0.5 * std::sin(1.0)), 1e-15);
  const double gas[5] = {2.0, 1.5, 3.0, 1.0, 4.0};   // I.44.4 n*kb*T*ln(V2/V1), V1 = 1, V2 = 4
  EXPECT_NEAR(find(table, "I.44.4").truth.evaluate(gas), 2.0 * 1.5 * 3.0 * std::log(4.0), 1e-12);
}

// Recovery, judged symbolically (hsr::symbolic_match: the canonical text after simplification must equal the
// published formula's, not just fit it), from 200 noise-free samples of the table's ranges, with a seed and a budget of
// seconds (population 1000, 3 restarts of 40 generations, stopping at round-off NMSE). The four are the table's
// easiest: products and halves of powers of the variables and the Gaussian, each recovered by the bench's full budget in
// < 3 s. A wrong sample range, a broken operator or a constant optimiser that stops short fails here.
TEST(FeynmanRecovery, EasyEquationsAreRecoveredSymbolically) {
  const auto table = hsr::read_feynman_table(kTable);
  for (const std::string id : {"I.12.1", "I.14.4", "I.43.31", "I.6.2a"}) {
    const auto& eq = find(table, id);
    const hsr::FeynmanSample data = hsr::sample_feynman(eq, 200, 17);
    auto s = hsr::full_engine_defaults();
    s.population_size = 1000;
    s.generations = 40;
    s.restarts = 3;
    s.seed = 1234;
    s.threads = 2;
    s.stopping_criteria = 1e-13;   // noise-free: the exact model reaches round-off level NMSE
    s.functions.clear();
    for (auto op : {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Sqrt, hsr::Op::Exp, hsr::Op::Cos}) {
      s.functions.push_back(op);   // the bench's function set
    }
    const auto fit = hsr::fit_validated(s, {}, data.x, data.y);
    const std::string text = hsr::to_infix(fit.expression, eq.names);
    EXPECT_TRUE(hsr::symbolic_match(fit.expression, eq.truth, eq.names)) << id << ": " << text << " vs " << eq.formula;
    std::printf("%s: %s (published %s)\n", id.c_str(), text.c_str(), eq.formula.c_str());
  }
}
