// SPDX-License-Identifier: MIT
// Reading FIT.toml into a FitRequest.
#include "closures/fit_request.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string_view>
#include <thread>

#include <fmt/format.h>

#include "closures/closure_inputs.hpp"
#include "common/config/config_file.hpp"

namespace hs::closures {
namespace {

using hs::common::ConfigSection;
namespace hsr = hs::regression;

std::vector<hsr::Op> read_functions(ConfigSection& s, const std::vector<hsr::Op>& defaults) {
  if (!s.has("functions")) return defaults;
  std::vector<hsr::Op> out;
  for (const auto& name : s.strings("functions")) {
    const auto op = hsr::op_from_name(name);
    if (!op) {
      std::string known;
      for (hsr::Op f : hsr::all_functions()) known += (known.empty() ? "" : ", ") + std::string(hsr::op_name(f));
      s.fail("functions", fmt::format("unknown function \"{}\" (allowed: {})", name, known));
    }
    out.push_back(*op);
  }
  return out;
}

void read_probabilities(ConfigSection& s, hsr::SearchSettings& r) {
  r.p_crossover = s.number_in_or("p_crossover", 0.0, 1.0, r.p_crossover);
  r.p_subtree_mutation = s.number_in_or("p_subtree_mutation", 0.0, 1.0, r.p_subtree_mutation);
  r.p_hoist_mutation = s.number_in_or("p_hoist_mutation", 0.0, 1.0, r.p_hoist_mutation);
  r.p_point_mutation = s.number_in_or("p_point_mutation", 0.0, 1.0, r.p_point_mutation);
  r.p_point_replace = s.number_in_or("p_point_replace", 0.0, 1.0, r.p_point_replace);
  const double sum = r.p_crossover + r.p_subtree_mutation + r.p_hoist_mutation + r.p_point_mutation;
  if (sum > 1.0 + 1e-12) s.fail("p_crossover", fmt::format("the four operator probabilities add up to {} > 1", sum));
}

/// The keys that set how long a search runs: with any of them the file states its own budget and starts from the
/// engine's plain settings; with none it gets default_fit_search's.
constexpr std::array<std::string_view, 5> kBudgetKeys{"population_size", "generations", "restarts", "stopping_criteria",
                                                      "max_seconds"};

/// The engine's settings with the file's budget to come: gplearn's or the full engine's, seed 0, every core
/// (a result does not depend on the thread count).
hsr::SearchSettings engine_settings(std::string_view engine) {
  hsr::SearchSettings r = engine == "gplearn" ? hsr::gplearn_defaults() : hsr::full_engine_defaults();
  r.seed = 0;
  r.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return r;
}

hsr::SearchSettings read_search(ConfigSection s) {
  const std::string engine = s.one_of_or("engine", {"full", "gplearn"}, "full");
  const bool budget_given = std::any_of(kBudgetKeys.begin(), kBudgetKeys.end(), [&](auto k) { return s.has(k); });
  hsr::SearchSettings r = budget_given ? engine_settings(engine) : default_fit_search(engine);
  r.functions = read_functions(s, r.functions);
  r.population_size = static_cast<int>(s.integer_in_or("population_size", 2, 10'000'000, r.population_size));
  r.generations = static_cast<int>(s.integer_in_or("generations", 1, 1'000'000, r.generations));
  r.tournament_size = static_cast<int>(s.integer_in_or("tournament_size", 1, r.population_size, r.tournament_size));
  const auto cr = s.has("const_range") ? s.numbers_in("const_range", -1e12, 1e12, 2) : std::vector{r.const_lo, r.const_hi};
  if (cr.size() != 2 || cr[0] > cr[1]) s.fail("const_range", "must be [lo, hi] with lo <= hi");
  r.const_lo = cr[0];
  r.const_hi = cr[1];
  r.use_constants = s.boolean_or("use_constants", r.use_constants);
  const auto depth = s.has("init_depth") ? s.numbers_in("init_depth", 1, 20, 2) : std::vector<double>{2.0, 6.0};
  if (depth.size() != 2 || depth[0] > depth[1]) s.fail("init_depth", "must be [lo, hi] with 1 <= lo <= hi <= 20");
  r.init_depth_lo = static_cast<int>(depth[0]);
  r.init_depth_hi = static_cast<int>(depth[1]);
  r.metric = hsr::metric_from_name(s.one_of_or("metric", {"mae", "mse", "rmse", "r2"}, hsr::metric_name(r.metric)));
  const bool auto_parsimony = s.boolean_or("parsimony_auto", false);
  r.parsimony_coefficient = auto_parsimony ? -1.0 : s.non_negative_or("parsimony_coefficient", r.parsimony_coefficient);
  read_probabilities(s, r);
  r.stopping_criteria = s.non_negative_or("stopping_criteria", r.stopping_criteria);
  r.max_length = static_cast<int>(s.integer_in_or("max_length", 0, 100000, r.max_length));
  r.linear_scaling = s.boolean_or("linear_scaling", r.linear_scaling);
  r.lm_iterations = static_cast<int>(s.integer_in_or("lm_iterations", 0, 1000, r.lm_iterations));
  r.max_seconds = s.non_negative_or("max_seconds", r.max_seconds);
  r.restarts = static_cast<int>(s.integer_in_or("restarts", 1, 1000, r.restarts));
  r.lexicase = s.boolean_or("lexicase", r.lexicase);
  r.penalise_duplicates = s.boolean_or("penalise_duplicates", r.penalise_duplicates);
  r.lm_max_rows = static_cast<int>(s.integer_in_or("lm_max_rows", 1, 1 << 30, r.lm_max_rows));
  r.selection_tolerance = s.number_in_or("selection_tolerance", 1.0, 1e6, r.selection_tolerance);
  r.seed = static_cast<std::uint64_t>(s.integer_in_or("seed", 0, std::numeric_limits<long>::max(),
                                                      static_cast<long>(r.seed)));
  r.threads = static_cast<int>(s.integer_in_or("threads", 1, 1024, r.threads));
  return r;
}

void read_data(ConfigSection root, FitRequest& r) {
  auto data = root.section("data");
  r.dataset = data.file_path("file");
  r.target = data.string("target");
  r.features = data.strings("features");
  auto derived = data.section_or_empty("derived");
  for (const auto& name : derived.keys()) {
    if (std::find(r.features.begin(), r.features.end(), name) == r.features.end()) {
      derived.fail(name, "is not among [data] features (a derived feature is computed only to be fitted on)");
    }
    r.derived.emplace_back(name, derived.string(name));
  }
  r.validation.test_fraction = data.number_in_or("test_fraction", 0.0, 0.9, 0.2);
  r.validation.folds = static_cast<int>(data.integer_in_or("folds", 0, 100, 5));
}

/// One unit string, checked: the key's own error (file, key, value, what is allowed) when it does not parse.
std::string checked_unit(ConfigSection& units, const std::string& key) {
  const std::string text = units.string(key);
  try {
    (void)hsr::parse_unit(text);
  } catch (const std::invalid_argument& e) {
    units.fail(key, e.what());
  }
  return text;
}

void read_units(ConfigSection root, FitRequest& r) {
  auto units = root.section_or_empty("units");
  for (const auto& key : units.keys()) {
    if (key != r.target && std::find(r.features.begin(), r.features.end(), key) == r.features.end()) {
      units.fail(key, "is neither the target nor a feature of [data]");
    }
  }
  for (const auto& f : r.features) {
    r.feature_units.push_back(units.has(f) ? checked_unit(units, f) : find_input(f) ? "1" : "");
  }
  r.target_unit = units.has(r.target) ? checked_unit(units, r.target) : r.kind != "generic" ? "1" : "";
}

void read_closure(ConfigSection root, FitRequest& r) {
  auto c = root.section("closure");
  r.name = c.string("name");
  r.kind = c.one_of("kind", {"drag", "lift", "deformation", "generic"});
  const std::string default_output = r.kind == "drag" ? "C_d" : r.kind == "lift" ? "C_l" : r.kind == "deformation" ? "DI" : r.target;
  r.output = c.string_or("output", default_output);
  if (r.kind == "lift") r.reference_velocity = c.one_of_or("reference_velocity", {"slip", "flow"}, "slip");
  auto vars = root.section_or_empty("variables");
  for (const auto& f : r.features) {
    const auto input = find_input(f);
    if (r.kind != "generic" && !input) {
      root.section("data").fail("features", fmt::format("\"{}\" is not a closure input; use kind = \"generic\"", f));
    }
    const auto derived = std::find_if(r.derived.begin(), r.derived.end(), [&](const auto& d) { return d.first == f; });
    const std::string fallback = input                       ? std::string(input->definition)
                                 : derived != r.derived.end() ? derived->second
                                                              : fmt::format("column {} of the dataset", f);
    r.definitions.push_back(vars.string_or(f, fallback));
  }
  read_units(root, r);
}

}  // namespace

hsr::SearchSettings default_fit_search(std::string_view engine) {
  hsr::SearchSettings r = engine_settings(engine);
  if (engine == "gplearn") return r;   // gplearn's own budget: 20 generations of 1000
  // The full engine's best use of about a minute on 2 cores (issue #29 item 2; measured by `bench feynman`):
  // 10 independent restarts of 40 generations (a fresh population each, the Pareto archive carried over),
  // stopping once the normalised error is at round-off (noise-free data: the formula is found), and a 60 s
  // wall-clock cap (reached only by slow data; a capped run is not reproducible across machines).
  r.generations = 400;
  r.restarts = 10;
  r.stopping_criteria = 1e-13;
  r.max_seconds = 60.0;
  return r;
}

FitRequest read_fit_request(const std::filesystem::path& file) {
  auto config = hs::common::ConfigFile::load(file, "fit file");
  auto root = config->root();
  FitRequest r;
  r.fit_file = file;
  read_data(root, r);
  read_closure(root, r);
  r.search = read_search(root.section_or_empty("search"));
  const bool all_units = !r.target_unit.empty() && std::none_of(r.feature_units.begin(), r.feature_units.end(),
                                                                [](const std::string& u) { return u.empty(); });
  if (all_units && root.section_or_empty("search").boolean_or("dimensional_constraints", true)) {
    for (const auto& u : r.feature_units) r.search.feature_dimensions.push_back(hsr::parse_unit(u));
    r.search.target_dimension = hsr::parse_unit(r.target_unit);
  }
  r.validation.select_from_front = true;
  r.plot = root.section_or_empty("output").boolean_or("plot", true);
  config->finish();
  return r;
}

}  // namespace hs::closures
