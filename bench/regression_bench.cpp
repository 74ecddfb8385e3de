// SPDX-License-Identifier: MIT
// `hemoscale bench regression`: recovery of 10 Feynman equations (gplearn defaults vs the full engine,
// same function set and budget) and the speed of the compiled evaluator.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/regression_bench.hpp"
#include "common/run_folder.hpp"
#include "regression/compiled_program.hpp"
#include "regression/infix.hpp"
#include "regression/model_selection.hpp"
#include "regression/polynomial.hpp"
#include "regression/simplify.hpp"

namespace hs::bench {
namespace {

namespace hsr = hs::regression;

// reference/validation/feynman_sr_subset10.csv (AI Feynman subset; formula, variables, sampling ranges).
constexpr const char* feynman_csv = R"(I.6.2a|exp(-theta**2/2)/sqrt(2*pi)|theta:[1,3]
I.8.14|sqrt((x2-x1)**2+(y2-y1)**2)|x1:[1,5]; x2:[1,5]; y1:[1,5]; y2:[1,5]
I.12.1|mu*Nn|mu:[1,5]; Nn:[1,5]
I.13.4|1/2*m*(v**2+u**2+w**2)|m:[1,5]; v:[1,5]; u:[1,5]; w:[1,5]
I.14.4|1/2*k_spring*x**2|k_spring:[1,5]; x:[1,5]
I.24.6|1/2*m*(omega**2+omega_0**2)*1/2*x**2|m:[1,3]; omega:[1,3]; omega_0:[1,3]; x:[1,3]
I.29.16|sqrt(x1**2+x2**2-2*x1*x2*cos(theta1-theta2))|x1:[1,5]; x2:[1,5]; theta1:[1,5]; theta2:[1,5]
I.39.22|n*kb*T/V|n:[1,5]; T:[1,5]; V:[1,5]; kb:[1,5]
I.43.31|mob*kb*T|mob:[1,5]; T:[1,5]; kb:[1,5]
I.47.23|sqrt(gamma*pr/rho)|gamma:[1,5]; pr:[1,5]; rho:[1,5])";

struct Equation {
  std::string id;
  std::string formula;
  std::vector<std::string> names;
  std::vector<double> lo, hi;
  hsr::Expression truth;
};

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

std::vector<Equation> equations() {
  std::vector<Equation> out;
  std::istringstream lines(feynman_csv);
  std::string line;
  while (std::getline(lines, line)) {
    Equation eq;
    const auto bar1 = line.find('|');
    const auto bar2 = line.find('|', bar1 + 1);
    eq.id = line.substr(0, bar1);
    eq.formula = line.substr(bar1 + 1, bar2 - bar1 - 1);
    std::istringstream vars(line.substr(bar2 + 1));
    std::string item;
    while (std::getline(vars, item, ';')) {
      const auto colon = item.find(':');
      eq.names.push_back(item.substr(item.find_first_not_of(' '), colon - item.find_first_not_of(' ')));
      eq.lo.push_back(std::stod(item.substr(item.find('[') + 1)));
      eq.hi.push_back(std::stod(item.substr(item.find(',') + 1)));
    }
    const std::string infix = replace_all(replace_all(eq.formula, "**", "^"), "pi", "3.141592653589793");
    eq.truth = hsr::parse_infix(infix, eq.names);
    out.push_back(std::move(eq));
  }
  return out;
}

struct Sample {
  std::vector<std::vector<double>> x;
  std::vector<double> y;
};

Sample sample(const Equation& eq, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Sample s{std::vector<std::vector<double>>(eq.names.size(), std::vector<double>(n)), std::vector<double>(n)};
  std::vector<double> point(eq.names.size());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < point.size(); ++j) {
      point[j] = s.x[j][i] = std::uniform_real_distribution<double>(eq.lo[j], eq.hi[j])(rng);
    }
    s.y[i] = eq.truth.evaluate(point.data());
  }
  return s;
}

struct Verdict {
  std::string expression;
  double r2_test = 0.0;
  double max_rel_error = 0.0;
  bool symbolic = false, exact = false;
  double seconds = 0.0;
};

std::string canonical(const hsr::Expression& e, const std::vector<std::string>& names) {
  constexpr auto mode = hsr::SimplifyMode::Algebraic;
  return hsr::to_infix(hsr::simplify(hsr::snap_constants(hsr::expand_polynomials(hsr::simplify(e, mode))), mode), names);
}

// Exact: the same canonical text as the truth, or test R^2 > 0.999999 with the right structure, taken to
// mean the same variables and a relative deviation <= 1e-4 everywhere on 1000 fresh points.
Verdict judge(const Equation& eq, const hsr::Expression& model, double seconds) {
  const Sample fresh = sample(eq, 1000, 4242);
  std::vector<double> p(fresh.y.size());
  hsr::CompiledProgram(model).evaluate(hsr::ColumnData(fresh.x).view(), p);
  Verdict v;
  v.expression = hsr::to_infix(model, eq.names);
  v.r2_test = hsr::r_squared(fresh.y, p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    v.max_rel_error = std::max(v.max_rel_error, std::abs(p[i] - fresh.y[i]) / std::abs(fresh.y[i]));
  }
  v.symbolic = canonical(model, eq.names) == canonical(eq.truth, eq.names);
  const bool right_structure = model.variables() == eq.truth.variables() && v.max_rel_error <= 1e-4;
  v.exact = v.symbolic || (v.r2_test > 0.999999 && right_structure);
  v.seconds = seconds;
  return v;
}

// The same budget for both configurations: population x generations (quick: a smoke test).
hsr::SearchSettings budget(hsr::SearchSettings s, bool quick, std::uint64_t seed) {
  s.population_size = quick ? 300 : 1000;
  s.generations = quick ? 16 : 400;
  s.functions.clear();   // element by element: GCC 12 warns falsely on assigning an initializer list here
  for (auto op : {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Sqrt, hsr::Op::Exp, hsr::Op::Cos}) {
    s.functions.push_back(op);
  }
  s.seed = seed;
  s.threads = 0;   // filled by the caller
  return s;
}

Verdict run_one(const Equation& eq, bool full, bool quick, int threads) {
  const Sample data = sample(eq, 400, 17);
  hsr::SearchSettings s = budget(full ? hsr::full_engine_defaults() : hsr::gplearn_defaults(), quick, 1234);
  s.threads = threads;
  if (full) {
    s.stopping_criteria = 1e-13;   // NMSE at round-off level: the exact model is found
    s.restarts = quick ? 2 : 10;   // independent runs (40 generations each) share the budget and the archive
  } else {
    s.max_seconds = 45.0;          // gplearn has no length limit: bloat could make 200 generations take hours
  }
  hsr::ValidationSettings v;
  v.test_fraction = 0.25;
  v.folds = full ? 5 : 0;
  v.select_from_front = full;
  const auto t0 = std::chrono::steady_clock::now();
  const auto fit = hsr::fit_validated(s, v, data.x, data.y);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return judge(eq, fit.expression, seconds);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v[(v.size() - 1) / 2] + v[v.size() / 2]) / 2.0;
}

}  // namespace

double evaluator_evaluations_per_second(int repetitions) {
  const std::vector<std::string> names{"x", "y", "z"};
  // 20 nodes: + - * / and sqrt, the mix a GP population is made of.
  const auto e = hsr::parse_infix("x*y + sqrt(z)*x - y/(z + 1.5) + 0.3*x*z", names);
  const std::size_t n = 1 << 20;
  std::vector<std::vector<double>> cols(3, std::vector<double>(n));
  std::mt19937_64 rng(1);
  for (auto& c : cols) {
    for (double& v : c) v = std::uniform_real_distribution<double>(0.5, 2.0)(rng);
  }
  const hsr::ColumnData data(cols);
  const hsr::CompiledProgram prog(e);
  std::vector<double> out(n);
  std::vector<double> rates;
  for (int r = 0; r < repetitions; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    prog.evaluate(data.view(), out);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(static_cast<double>(n) / s);
  }
  if (e.size() != 20) throw std::logic_error("evaluator benchmark expression must have 20 nodes");
  return median(rates);
}

int run_regression_bench(const hs::common::TaskOptions& options) {
  const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const double rate = evaluator_evaluations_per_second(7);
  fmt::print("evaluator: {:.3g} evaluations/s (20-node expression, one core, median of 7)\n", rate);
  nlohmann::json per_equation = nlohmann::json::array();
  int exact_full = 0, r2_full = 0, exact_gplearn = 0, r2_gplearn = 0;
  std::vector<double> sec_full, sec_gplearn;
  for (const auto& eq : equations()) {
    const Verdict g = run_one(eq, false, options.quick, threads);
    const Verdict f = run_one(eq, true, options.quick, threads);
    exact_full += f.exact ? 1 : 0;
    r2_full += f.r2_test > 0.999 ? 1 : 0;
    exact_gplearn += g.exact ? 1 : 0;
    r2_gplearn += g.r2_test > 0.999 ? 1 : 0;
    sec_full.push_back(f.seconds);
    sec_gplearn.push_back(g.seconds);
    fmt::print("{:8} full    exact={:d} R2={:.9f} {:6.1f}s  {}\n", eq.id, f.exact, f.r2_test, f.seconds, f.expression);
    fmt::print("{:8} gplearn exact={:d} R2={:.9f} {:6.1f}s  {}\n", eq.id, g.exact, g.r2_test, g.seconds, g.expression);
    per_equation.push_back({{"id", eq.id}, {"formula", eq.formula},
                            {"full", {{"expression", f.expression}, {"r2_test", f.r2_test}, {"exact", f.exact},
                                      {"symbolic_match", f.symbolic}, {"seconds", f.seconds}}},
                            {"gplearn", {{"expression", g.expression}, {"r2_test", g.r2_test}, {"exact", g.exact},
                                         {"symbolic_match", g.symbolic}, {"seconds", g.seconds}}}});
  }
  fmt::print("exact recovery: full {}/10, gplearn {}/10; test R2 > 0.999: full {}/10, gplearn {}/10\n", exact_full,
             exact_gplearn, r2_full, r2_gplearn);
  fmt::print("seconds per equation (median): full {:.1f}, gplearn {:.1f} ({} threads)\n", median(sec_full),
             median(sec_gplearn), threads);
  if (options.json_file) {
    nlohmann::json j{{"exact_full", exact_full}, {"r2_full", r2_full}, {"exact_gplearn", exact_gplearn},
                     {"r2_gplearn", r2_gplearn}, {"seconds_median", median(sec_full)},
                     {"seconds_median_gplearn", median(sec_gplearn)}, {"threads", threads},
                     {"evaluations_per_second", rate}, {"quick", options.quick}, {"equations", per_equation},
                     {"provenance", hs::common::provenance()}};
    hs::common::write_json(*options.json_file, j);
  }
  return 0;
}

}  // namespace hs::bench
