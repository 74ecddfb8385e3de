// SPDX-License-Identifier: MIT
// The search recovers known formulas exactly from noise-free data, and is reproducible for a seed.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "regression/compiled_program.hpp"
#include "regression/infix.hpp"
#include "regression/model_selection.hpp"

namespace hsr = hs::regression;

namespace {

struct Data {
  std::vector<std::vector<double>> x;
  std::vector<double> y;
};

template <class F>
Data sample(std::size_t n, std::size_t n_vars, double lo, double hi, std::uint64_t seed, F f) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  Data d{std::vector<std::vector<double>>(n_vars, std::vector<double>(n)), std::vector<double>(n)};
  std::vector<double> point(n_vars);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n_vars; ++j) point[j] = d.x[j][i] = u(rng);
    d.y[i] = f(point.data());
  }
  return d;
}

hsr::SearchSettings small_full_engine(std::uint64_t seed, int threads) {
  auto s = hsr::full_engine_defaults();
  s.population_size = 300;
  s.generations = 30;
  s.seed = seed;
  s.threads = threads;
  s.stopping_criteria = 1e-14;   // noise-free: an exact model reaches round-off level NMSE
  return s;
}

// Largest relative deviation of `e` from `truth` on fresh points (not the training data).
template <class F>
double max_relative_error(const hsr::Expression& e, std::size_t n_vars, double lo, double hi, F truth) {
  const Data fresh = sample(500, n_vars, lo, hi, 999, truth);
  double worst = 0.0;
  std::vector<double> point(n_vars);
  for (std::size_t i = 0; i < fresh.y.size(); ++i) {
    for (std::size_t j = 0; j < n_vars; ++j) point[j] = fresh.x[j][i];
    worst = std::max(worst, std::abs(e.evaluate(point.data()) - fresh.y[i]) / std::max(std::abs(fresh.y[i]), 1e-12));
  }
  return worst;
}

}  // namespace

TEST(Recovery, QuadraticPolynomial) {
  auto truth = [](const double* v) { return 2.5 * v[0] * v[0] + v[0]; };
  const Data d = sample(100, 1, -2.0, 2.0, 1, truth);
  const auto fit = hsr::fit_validated(small_full_engine(7, 2), {}, d.x, d.y);
  const std::string text = hsr::to_infix(fit.expression, {"x"});
  // Exact recovery: relative error at round-off level (1e-9 leaves room for LM's last digits) with at most
  // the 7 nodes of x*(2.5*x + 1) plus one.
  EXPECT_LT(max_relative_error(fit.expression, 1, -2.0, 2.0, truth), 1e-9) << text;
  EXPECT_LE(fit.expression.size(), 8u) << text;
  EXPECT_GT(fit.test.r2, 1.0 - 1e-12) << text;
  // Every expression the search produced (the model and the whole Pareto front) round-trips through the parser.
  EXPECT_EQ(hsr::parse_infix(text, {"x"}), fit.expression);
  for (const auto& entry : fit.front) {
    EXPECT_EQ(hsr::parse_infix(hsr::to_infix(entry.expression, {"x"}), {"x"}), entry.expression);
  }
}

TEST(Recovery, RationalFunction) {
  auto truth = [](const double* v) { return v[0] / (1.0 + v[1]); };
  const Data d = sample(100, 2, 0.5, 3.0, 2, truth);
  const auto fit = hsr::fit_validated(small_full_engine(11, 2), {}, d.x, d.y);
  const std::string text = hsr::to_infix(fit.expression, {"x", "y"});
  EXPECT_LT(max_relative_error(fit.expression, 2, 0.5, 3.0, truth), 1e-9) << text;   // see above
  EXPECT_LE(fit.expression.size(), 7u) << text;   // x/(1 + y) has 5 nodes; allow a scale factor
  EXPECT_EQ(hsr::parse_infix(text, {"x", "y"}), fit.expression);
  for (const auto& entry : fit.front) {
    EXPECT_EQ(hsr::parse_infix(hsr::to_infix(entry.expression, {"x", "y"}), {"x", "y"}), entry.expression);
  }
}

TEST(Recovery, SameSeedSameResultForAnyThreadCount) {
  auto truth = [](const double* v) { return std::sin(v[0]) * v[1] + 0.3; };
  const Data d = sample(80, 2, -1.0, 1.0, 3, truth);
  auto s = small_full_engine(5, 1);
  s.generations = 5;
  s.stopping_criteria = 0.0;
  s.functions = {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Sin, hsr::Op::Cos};
  const auto one = hsr::fit_validated(s, {}, d.x, d.y);
  s.threads = 2;
  const auto two = hsr::fit_validated(s, {}, d.x, d.y);
  const auto again = hsr::fit_validated(s, {}, d.x, d.y);
  EXPECT_EQ(one.expression, two.expression);
  EXPECT_EQ(two.expression, again.expression);
  EXPECT_EQ(one.search.evaluations, two.search.evaluations);
  ASSERT_EQ(one.front.size(), two.front.size());
  for (std::size_t i = 0; i < one.front.size(); ++i) EXPECT_EQ(one.front[i].expression, two.front[i].expression);
}

TEST(Recovery, LexicaseAndRestartsAreReproducibleToo) {
  auto truth = [](const double* v) { return v[0] * v[1] - v[0]; };
  const Data d = sample(60, 2, -1.0, 1.0, 6, truth);
  auto s = small_full_engine(8, 1);
  s.generations = 6;
  s.restarts = 2;
  s.lexicase = true;
  s.stopping_criteria = 0.0;
  const auto one = hsr::fit_validated(s, {}, d.x, d.y);
  s.threads = 2;
  const auto two = hsr::fit_validated(s, {}, d.x, d.y);
  EXPECT_EQ(one.expression, two.expression);
  EXPECT_EQ(one.search.evaluations, two.search.evaluations);
}

TEST(Recovery, GplearnDefaultsRunReproducibly) {
  auto truth = [](const double* v) { return v[0] * v[0] + v[0]; };
  const Data d = sample(50, 1, -1.0, 1.0, 4, truth);
  auto s = hsr::gplearn_defaults();
  s.population_size = 200;
  s.generations = 5;
  s.threads = 2;
  s.seed = 1;
  const auto a = hsr::fit_validated(s, {}, d.x, d.y);
  const auto a2 = hsr::fit_validated(s, {}, d.x, d.y);
  EXPECT_EQ(a.expression, a2.expression);
  EXPECT_TRUE(std::isfinite(a.train.mae));
  EXPECT_LE(a.search.generations_run, 5);
}
