// SPDX-License-Identifier: MIT
// `hemoscale bench regression`: recovery of 10 Feynman equations (gplearn defaults vs the full engine,
// same function set and budget) and the speed of the compiled evaluator. HS_BENCH_REGRESSION_ARCHIVE=FILE (a JSON
// this bench wrote) reuses the models FILE holds instead of searching again and judges them anew: the full budget
// takes minutes of every core, so the failure-path test gives the bench a committed full run this way.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "bench/regression_bench.hpp"
#include "bench/bench_targets.hpp"
#include "common/check_list.hpp"
#include "common/errors.hpp"
#include "common/run_folder.hpp"
#include "regression/compiled_program.hpp"
#include "regression/feynman_table.hpp"
#include "regression/infix.hpp"
#include "regression/model_selection.hpp"
#include "regression/recovery_judge.hpp"

namespace hs::bench {
namespace {

namespace hsr = hs::regression;

/// The committed table (data/reference/feynman_sr_subset10.csv, AI Feynman subset: formula, variables, sampling ranges).
const char* const feynman_csv = HS_DATA_DIR "/reference/feynman_sr_subset10.csv";

/// Documented target (issue 29, "the ten equations of today's bench stay at 10/10"): every equation recovered
/// exactly by the full engine at the full budget.
constexpr double kTargetExactFull = 10.0;

using Equation = hsr::FeynmanEquation;
using Sample = hsr::FeynmanSample;

Sample sample(const Equation& eq, std::size_t n, std::uint64_t seed) { return hsr::sample_feynman(eq, n, seed); }

/// A recovery verdict (regression/recovery_judge.hpp: noise-free, so canonical forms at 1e-6 or the numeric rule)
/// and the search's wall time.
struct Timed : hsr::RecoveryVerdict {
  double seconds = 0.0;
};

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

Timed run_one(const Equation& eq, bool full, bool quick, int threads) {
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
  return {hsr::judge_recovery(eq, fit.expression, 0.0), seconds};
}

/// The environment variable naming an earlier run's JSON whose models are reused (see the file comment).
constexpr const char* archive_env = "HS_BENCH_REGRESSION_ARCHIVE";

/// An archived model judged as a fresh search's would be: the expression FILE recorded, parsed in the table's variable
/// names and given to the same judge; the wall time is the archived search's.
Timed judge_archived(const Equation& eq, const nlohmann::json& entry) {
  const hsr::Expression model = hsr::parse_infix(entry.at("expression").get<std::string>(), eq.names);
  return {hsr::judge_recovery(eq, model, 0.0), entry.at("seconds").get<double>()};
}

/// The per-equation entries of an archived run, by equation id; empty without the environment variable. A run of
/// the other budget (--quick against full) is refused: its models are not what this run would have searched for.
std::map<std::string, nlohmann::json> read_archive(bool quick) {
  const char* file = std::getenv(archive_env);
  if (file == nullptr) return {};
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!in || j.is_discarded() || !j.contains("equations") || !j.contains("quick")) {
    throw hs::common::ConfigError(fmt::format("{}={}: not a JSON written by `hemoscale bench regression --json` "
                                              "(needs \"equations\" and \"quick\")", archive_env, file));
  }
  if (j["quick"].get<bool>() != quick) {
    throw hs::common::ConfigError(fmt::format("{}={}: holds a {} run, this run is {}; allowed: an archive of the same "
                                              "budget", archive_env, file, j["quick"].get<bool>() ? "--quick" : "full",
                                              quick ? "--quick" : "full"));
  }
  std::map<std::string, nlohmann::json> out;
  for (const auto& e : j["equations"]) out[e.at("id").get<std::string>()] = e;
  fmt::print("reusing the models of {} (written {}, commit {}); equations it lacks are searched\n", file,
             j.value(nlohmann::json::json_pointer("/provenance/written_utc"), std::string("?")),
             j.value(nlohmann::json::json_pointer("/provenance/git_commit"), std::string("?")));
  return out;
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
  const std::vector<Equation> table = hsr::read_feynman_table(feynman_csv);
  const std::map<std::string, nlohmann::json> archived = read_archive(options.quick);
  std::vector<std::string> missed;
  int searched = 0;
  for (const auto& eq : table) {
    const auto it = archived.find(eq.id);
    // An entry of another formula (the table changed since) is searched again.
    const bool reuse = it != archived.end() && it->second.value("formula", std::string()) == eq.formula;
    const Timed g = reuse ? judge_archived(eq, it->second.at("gplearn")) : run_one(eq, false, options.quick, threads);
    const Timed f = reuse ? judge_archived(eq, it->second.at("full")) : run_one(eq, true, options.quick, threads);
    searched += reuse ? 0 : 1;
    exact_full += f.exact ? 1 : 0;
    if (!f.exact) missed.push_back(eq.id);
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
  const int n_eq = static_cast<int>(table.size());
  fmt::print("exact recovery: full {}/{}, gplearn {}/{}; test R2 > 0.999: full {}/{}, gplearn {}/{}\n", exact_full, n_eq,
             exact_gplearn, n_eq, r2_full, n_eq, r2_gplearn, n_eq);
  // The target is judged at the full budget only: --quick (300 x 16) is a smoke test, its check is skipped.
  hs::common::CheckList checks;
  const std::optional<double> measured = options.quick ? std::nullopt : std::optional<double>(exact_full);
  expect_at_least(checks, options, "exact_full", measured, kTargetExactFull,
                  "issue #29: the ten equations of the bench stay at 10/10");
  if (!missed.empty()) fmt::print("not recovered exactly by the full engine: {}\n", fmt::join(missed, ", "));
  fmt::print("seconds per equation (median): full {:.1f}, gplearn {:.1f} ({} threads)\n", median(sec_full),
             median(sec_gplearn), threads);
  if (options.json_file) {
    nlohmann::json j{{"exact_full", exact_full}, {"missed_full", missed}, {"r2_full", r2_full}, {"exact_gplearn", exact_gplearn},
                     {"r2_gplearn", r2_gplearn}, {"seconds_median", median(sec_full)},
                     {"seconds_median_gplearn", median(sec_gplearn)}, {"threads", threads},
                     {"evaluations_per_second", rate}, {"quick", options.quick}, {"equations", per_equation},
                     {"equations_searched_this_run", searched},
                     {"provenance", hs::common::provenance()}};
    checks.write_to(j);
    hs::common::write_json(*options.json_file, j);
  }
  checks.print("bench regression");
  return checks.exit_code();
}

}  // namespace hs::bench
