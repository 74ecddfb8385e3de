// SPDX-License-Identifier: MIT
// `hemoscale bench feynman`: the AI-Feynman table through the code path of `hemoscale fit`, resumable.
#include "bench/feynman_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/bench_targets.hpp"
#include "closures/fit_request.hpp"
#include "closures/sha256.hpp"
#include "common/check_list.hpp"
#include "common/run_folder.hpp"
#include "regression/feynman_table.hpp"
#include "regression/infix.hpp"
#include "regression/model_selection.hpp"
#include "regression/recovery_judge.hpp"

namespace hs::bench {
namespace {

namespace hsr = hs::regression;

const char* const kTable = HS_DATA_DIR "/reference/feynman_ai100.csv";

/// Issue #29's targets at noise 0 and 0.01: above AI Feynman's 55.8% and gplearn's 13.2% exact-solution rates on
/// the Feynman set in SRBench 2021 (La Cava et al., NeurIPS datasets track).
constexpr double kTargetExactNoise0 = 60.0;
constexpr double kTargetExactNoise001 = 20.0;

/// 400 rows per search (the fit keeps 20% of them out as its own test set), as the ten-equation bench.
constexpr std::size_t kRows = 400;

/// The functions both configurations may use: SRBench's usual set for the Feynman problems plus tanh and asin,
/// which the table's formulas contain (II.35.21, I.26.2, I.30.5); none is chosen per equation.
std::vector<hsr::Op> feynman_functions() {
  std::vector<hsr::Op> f;
  for (auto op : {hsr::Op::Add, hsr::Op::Sub, hsr::Op::Mul, hsr::Op::Div, hsr::Op::Sqrt, hsr::Op::Exp, hsr::Op::Log,
                  hsr::Op::Sin, hsr::Op::Cos, hsr::Op::Tanh, hsr::Op::Asin}) {
    f.push_back(op);
  }
  return f;
}

struct Configuration {
  std::string name;
  hsr::SearchSettings search;
  hsr::ValidationSettings validation;
};

/// "hemoscale": exactly `hemoscale fit`'s defaults (closures::default_fit_search and the [data] validation defaults)
/// with the function set above. "gplearn": gplearn's defaults and its choice of model (lowest training loss), at the
/// same population, generations and wall-clock cap (restarts are the full engine's, not a budget). --quick
/// shrinks the budget of both alike.
std::vector<Configuration> configurations(bool quick, int threads) {
  Configuration ours{"hemoscale", hs::closures::default_fit_search("full"), {}};
  Configuration theirs{"gplearn", hs::closures::default_fit_search("gplearn"), {}};
  theirs.validation.folds = 0;
  theirs.validation.select_from_front = false;
  if (quick) {
    ours.search.population_size = 300;
    ours.search.generations = 20;
    ours.search.restarts = 2;
  }
  // No wall-clock cap in the bench: a capped search's result depends on the machine's load, and the bench must
  // give the same rates on any machine; the generations are the fit default's (its 60 s cap binds only on slow
  // data or a loaded machine). gplearn has no length limit, so its bloat could take hours: it keeps a 300 s cap.
  ours.search.max_seconds = 0.0;
  theirs.search.population_size = ours.search.population_size;
  theirs.search.generations = ours.search.generations;
  theirs.search.max_seconds = 300.0;
  std::vector<Configuration> out{ours, theirs};
  for (auto& c : out) {
    c.search.functions = feynman_functions();
    c.search.threads = threads;   // results do not depend on it (SymbolicRegressor), the wall clock does
  }
  return out;
}

/// Everything that decides a search's result, hashed: an archived result is reused only under the same one.
std::string fingerprint(const Configuration& c, const std::string& table_sha) {
  const auto& s = c.search;
  std::string text = fmt::format("{}|{}|rows {}|pop {}|gen {}|tour {}|len {}|pars {}|ls {}|lm {} {}|rs {}|dup {}|lex {}|"
                                 "sec {}|metric {}|p {} {} {} {} {}|c {} {}|sel {}|val {} {} {}|f",
                                 c.name, table_sha, kRows, s.population_size, s.generations, s.tournament_size,
                                 s.max_length, s.parsimony_coefficient, s.linear_scaling, s.lm_iterations, s.lm_max_rows,
                                 s.restarts, s.penalise_duplicates, s.lexicase, s.max_seconds, hsr::metric_name(s.metric),
                                 s.p_crossover, s.p_subtree_mutation, s.p_hoist_mutation, s.p_point_mutation,
                                 s.p_point_replace, s.const_lo, s.const_hi, s.selection_tolerance,
                                 c.validation.test_fraction, c.validation.folds, c.validation.select_from_front);
  for (auto op : s.functions) text += fmt::format(" {}", hsr::op_name(op));
  return hs::closures::sha256_hex(text).substr(0, 16);
}

/// The training rows of one search: the table's sample plus Gaussian noise of `level` std(y), seeded per run.
hsr::FeynmanSample noisy_sample(const hsr::FeynmanEquation& eq, double level, std::uint64_t seed) {
  hsr::FeynmanSample data = hsr::sample_feynman(eq, kRows, 17 + seed);
  if (level == 0.0) return data;
  double mean = 0.0, var = 0.0;
  for (double y : data.y) mean += y / static_cast<double>(data.y.size());
  for (double y : data.y) var += (y - mean) * (y - mean) / static_cast<double>(data.y.size());
  std::mt19937_64 rng(seed * 1000003ULL + static_cast<std::uint64_t>(std::llround(level * 1e6)));
  std::normal_distribution<double> noise(0.0, level * std::sqrt(var));
  for (double& y : data.y) y += noise(rng);
  return data;
}

std::string run_key(const std::string& config, const std::string& id, double noise, std::uint64_t seed) {
  return fmt::format("{}|{}|{}|{}", config, id, noise, seed);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v[(v.size() - 1) / 2] + v[v.size() / 2]) / 2.0;
}

/// FILE.json -> FILE + suffix (FILE.runs.jsonl, FILE_equations.csv).
std::filesystem::path beside(const std::filesystem::path& json, const std::string& suffix) {
  return json.parent_path() / (json.stem().string() + suffix);
}

/// What one run searches: equations, noise levels, seeds and configurations (the full table, or --quick's subset).
struct Plan {
  std::vector<hsr::FeynmanEquation> table;
  std::string table_sha;
  std::vector<double> noise_levels{0.0, 0.001, 0.01};
  std::vector<std::uint64_t> seeds{1, 2, 3};
  std::vector<Configuration> configs;
};

Plan make_plan(bool quick, int threads) {
  Plan p;
  p.table = hsr::read_feynman_table(kTable);
  p.table_sha = hs::closures::sha256_file(kTable).substr(0, 16);
  if (quick) {   // every tenth equation, two noise levels, one seed: a smoke test of the whole path
    std::vector<hsr::FeynmanEquation> every_tenth;
    for (std::size_t i = 0; i < p.table.size(); i += 10) every_tenth.push_back(p.table[i]);
    p.table = std::move(every_tenth);
    p.noise_levels = {0.0, 0.01};
    p.seeds = {1};
  }
  p.configs = configurations(quick, threads);
  return p;
}

/// A search's archive line takes the judge's verdict (and the judge's version).
void set_verdict(nlohmann::json& j, const hsr::RecoveryVerdict& v) {
  j["exact"] = v.exact;
  j["exact_strict"] = v.exact_strict;
  j["symbolic"] = v.symbolic;
  j["numeric"] = v.numeric;
  j["r2_test"] = v.r2_test;
  j["max_rel_error"] = v.max_rel_error;
  j["judge"] = hsr::kRecoveryJudgeVersion;
}

/// An archived search's verdict by the current judge: the search is not repeated, its printed formula is judged
/// again when an older judge wrote the verdict (a formula that does not parse keeps its verdict).
nlohmann::json judged_again(nlohmann::json j, const hsr::FeynmanEquation& eq, double noise) {
  if (j.value("judge", 1) >= hsr::kRecoveryJudgeVersion) return j;
  try {
    set_verdict(j, hsr::judge_recovery(eq, hsr::parse_infix(j.at("expression").get<std::string>(), eq.names), noise));
  } catch (const hsr::ParseError&) {
    // not a formula of this table's variables: the archived verdict stands
  }
  return j;
}

}  // namespace

std::vector<FeynmanSearchId> feynman_searches(bool quick) {
  const Plan plan = make_plan(quick, 1);   // the thread count is not part of a search's fingerprint
  std::vector<FeynmanSearchId> out;
  for (const std::uint64_t seed : plan.seeds) {
    for (const double noise : plan.noise_levels) {
      for (const auto& c : plan.configs) {
        const std::string fp = fingerprint(c, plan.table_sha);
        for (const auto& eq : plan.table) out.push_back({run_key(c.name, eq.id, noise, seed), fp, c.name, eq.id, noise, seed});
      }
    }
  }
  return out;
}

int run_feynman_bench(const hs::common::TaskOptions& options) {
  const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const Plan plan = make_plan(options.quick, threads);
  const auto& table = plan.table;
  const std::string& table_sha = plan.table_sha;
  const auto& noise_levels = plan.noise_levels;
  const auto& seeds = plan.seeds;
  const auto& configs = plan.configs;

  // The archive: one JSON line per finished search, keyed by configuration, equation, noise and seed.
  std::map<std::string, nlohmann::json> done;
  std::optional<std::filesystem::path> archive;
  if (options.json_file) {
    archive = beside(*options.json_file, ".runs.jsonl");
    std::filesystem::create_directories(archive->parent_path().empty() ? "." : archive->parent_path());
    std::ifstream in(*archive);
    for (std::string line; std::getline(in, line);) {
      if (line.empty()) continue;
      const auto j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_discarded() || !j.contains("key")) continue;   // a line cut short by a crash
      done[j["key"].get<std::string>() + "#" + j.value("fingerprint", "")] = j;
    }
  }
  std::ofstream append;
  if (archive) append.open(*archive, std::ios::app);

  const std::size_t total = configs.size() * noise_levels.size() * seeds.size() * table.size();
  std::size_t finished = 0, computed = 0;
  double computed_seconds = 0.0;
  std::vector<nlohmann::json> results;
  // Seed outermost: an interrupted run has whole seeds of every configuration and noise level to compare.
  for (const std::uint64_t seed : seeds) {
    for (const double noise : noise_levels) {
      for (const auto& c : configs) {
        const std::string fp = fingerprint(c, table_sha);
        for (const auto& eq : table) {
          const std::string key = run_key(c.name, eq.id, noise, seed);
          ++finished;
          if (const auto it = done.find(key + "#" + fp); it != done.end()) {
            results.push_back(judged_again(it->second, eq, noise));
            continue;
          }
          const hsr::FeynmanSample data = noisy_sample(eq, noise, seed);
          hsr::SearchSettings s = c.search;
          s.seed = seed;
          const auto t0 = std::chrono::steady_clock::now();
          const auto fit = hsr::fit_validated(s, c.validation, data.x, data.y);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          const hsr::RecoveryVerdict v = hsr::judge_recovery(eq, fit.expression, noise);
          nlohmann::json j{{"key", key},     {"fingerprint", fp},  {"config", c.name},
                           {"id", eq.id},    {"noise", noise},     {"seed", seed},
                           {"seconds", seconds}, {"expression", v.expression}, {"formula", eq.formula}};
          set_verdict(j, v);
          if (append.is_open()) append << j.dump() << "\n" << std::flush;
          results.push_back(j);
          ++computed;
          computed_seconds += seconds;
          const double eta = computed_seconds / static_cast<double>(computed) * static_cast<double>(total - finished);
          fmt::print("[{}/{}] {:9} {:8} noise {:<5} seed {} exact={:d} R2={:.6f} {:5.1f}s  ETA {:.0f} min  {}\n",
                     finished, total, c.name, eq.id, noise, seed, v.exact, v.r2_test, seconds, eta / 60.0, v.expression);
        }
      }
    }
  }

  // Rates per configuration and noise level, over equations and seeds.
  nlohmann::json summary = nlohmann::json::object();
  std::map<std::string, double> exact_rate;
  for (const auto& c : configs) {
    for (const double noise : noise_levels) {
      int exact = 0, strict = 0, r2_good = 0, n = 0;
      std::vector<double> secs;
      for (const auto& j : results) {
        if (j["config"] != c.name || j["noise"].get<double>() != noise) continue;
        ++n;
        exact += j["exact"].get<bool>() ? 1 : 0;
        strict += j["exact_strict"].get<bool>() ? 1 : 0;
        r2_good += j["r2_test"].get<double>() > 0.999 ? 1 : 0;
        secs.push_back(j["seconds"].get<double>());
      }
      const std::string tag = fmt::format("{}_noise{}", c.name, noise);
      const double rate = n > 0 ? 100.0 * exact / n : 0.0;
      exact_rate[tag] = rate;
      summary[tag] = {{"exact_percent", rate}, {"exact_strict_percent", n > 0 ? 100.0 * strict / n : 0.0},
                      {"r2_above_0_999_percent", n > 0 ? 100.0 * r2_good / n : 0.0},
                      {"searches", n}, {"seconds_median", median(secs)}};
      fmt::print("{:9} noise {:<5}: exact {:5.1f}% (strict {:5.1f}%)  R2 > 0.999 {:5.1f}%  ({} searches, median {:.1f} s)\n",
                 c.name, noise, rate, n > 0 ? 100.0 * strict / n : 0.0, n > 0 ? 100.0 * r2_good / n : 0.0, n,
                 median(secs));
    }
  }

  // The targets are judged on the full table only: --quick is a smoke test of the path, its checks are skipped.
  hs::common::CheckList checks;
  auto measured = [&](const std::string& tag) {
    return options.quick ? std::nullopt : std::optional<double>(exact_rate[tag]);
  };
  expect_at_least(checks, options, "exact_percent_noise0", measured("hemoscale_noise0"), kTargetExactNoise0,
                  "issue #29: above AI Feynman's 55.8% in SRBench 2021");
  expect_at_least(checks, options, "exact_percent_noise0.01", measured("hemoscale_noise0.01"), kTargetExactNoise001,
                  "issue #29: above gplearn's 13.2% in SRBench 2021");
  if (options.json_file) {
    std::ofstream csv(beside(*options.json_file, "_equations.csv"));
    csv << "config,id,noise,seed,exact,exact_strict,symbolic,numeric,r2_test,max_rel_error,seconds,expression\n";
    for (const auto& j : results) {
      csv << fmt::format("{},{},{},{},{:d},{:d},{:d},{:d},{:.9g},{:.3g},{:.2f},\"{}\"\n", j["config"].get<std::string>(),
                         j["id"].get<std::string>(), j["noise"].get<double>(), j["seed"].get<std::uint64_t>(),
                         j["exact"].get<bool>(), j["exact_strict"].get<bool>(), j["symbolic"].get<bool>(),
                         j["numeric"].get<bool>(),
                         j["r2_test"].get<double>(), j["max_rel_error"].get<double>(), j["seconds"].get<double>(),
                         j["expression"].get<std::string>());
    }
    nlohmann::json out{{"equations", table.size()}, {"noise_levels", noise_levels}, {"seeds", seeds},
                       {"rows", kRows}, {"threads", threads}, {"quick", options.quick}, {"rates", summary},
                       {"exact_percent_noise0", exact_rate["hemoscale_noise0"]},
                       {"exact_percent_noise0.01", exact_rate["hemoscale_noise0.01"]},
                       {"exact_percent_noise0_gplearn", exact_rate["gplearn_noise0"]},
                       {"exact_percent_noise0.01_gplearn", exact_rate["gplearn_noise0.01"]},
                       {"searches_computed_this_run", computed}, {"provenance", hs::common::provenance()}};
    checks.write_to(out);
    hs::common::write_json(*options.json_file, out);
  }
  checks.print("bench feynman");
  return checks.exit_code();
}

}  // namespace hs::bench
