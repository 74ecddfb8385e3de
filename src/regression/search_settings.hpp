// SPDX-License-Identifier: MIT
// Every knob of the symbolic-regression search; the defaults are gplearn's SymbolicRegressor defaults
// (gplearn/genetic.py __init__, see reference/unresolved-methods.md 6.1) unless marked "beyond gplearn".
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "regression/dimension.hpp"
#include "regression/metrics.hpp"
#include "regression/op.hpp"

namespace hs::regression {

/// gplearn's default function_set.
[[nodiscard]] inline std::vector<Op> gplearn_function_set() {
  std::vector<Op> f;
  for (Op op : {Op::Add, Op::Sub, Op::Mul, Op::Div}) f.push_back(op);
  return f;
}

struct SearchSettings {
  // --- gplearn's parameters and defaults ---
  int population_size = 1000;
  int generations = 20;
  int tournament_size = 20;
  double stopping_criteria = 0.0;            // stop when the best raw loss <= this
  bool use_constants = true;                 // gplearn const_range=None switches constants off
  double const_lo = -1.0;                    // const_range (-1, 1)
  double const_hi = 1.0;
  int init_depth_lo = 2;                     // init_depth (2, 6)
  int init_depth_hi = 6;
  std::vector<Op> functions = gplearn_function_set();   // ('add', 'sub', 'mul', 'div')
  Metric metric = Metric::Mae;               // 'mean absolute error'
  double parsimony_coefficient = 0.001;
  double p_crossover = 0.9;
  double p_subtree_mutation = 0.01;
  double p_hoist_mutation = 0.01;
  double p_point_mutation = 0.01;
  double p_point_replace = 0.05;
  std::uint64_t seed = 0;                    // random_state
  int threads = 1;                           // n_jobs (results do not depend on it, see SymbolicRegressor)

  // --- beyond gplearn ---
  int max_length = 0;                        // reject offspring longer than this (0 = no limit, gplearn)
  bool linear_scaling = false;               // fit y ~ a + b f(x) in closed form (Keijzer 2003)
  int lm_iterations = 0;                     // Levenberg-Marquardt steps on the constants per offspring (Operon)
  int lm_max_rows = 256;                     // LM works on at most this many rows (evenly strided)
  bool lexicase = false;                     // epsilon-lexicase instead of tournament selection
  int lexicase_cases = 128;                  // at most this many training rows (evenly strided) as cases
  int restarts = 1;                          // independent runs sharing the generations and the Pareto archive
  bool penalise_duplicates = false;          // clones (same loss and length) lose every tournament but one
  double max_seconds = 0.0;                  // wall-clock budget (0 = none); breaks reproducibility if hit
  double selection_tolerance = 1.5;          // Pareto model choice: simplest with loss <= tol * best (PySR uses 1.5)

  // --- dimensional constraints (beyond gplearn; as PySR's, with constants as wildcards) ---
  std::vector<Dimension> feature_dimensions;   // empty: none; else one per feature
  std::optional<Dimension> target_dimension;   // the output's (free under linear scaling: the scale takes it)
};

/// gplearn's defaults (the "gplearn" configuration of the benchmark).
[[nodiscard]] inline SearchSettings gplearn_defaults() { return SearchSettings{}; }

/// The full engine: gplearn's operators (with more mutation) plus linear scaling, LM constant fitting, a
/// length limit, duplicate penalty and an R^2 (= normalised MSE) loss; parsimony is lower because the Pareto
/// front, not the penalty, picks the size.
[[nodiscard]] inline SearchSettings full_engine_defaults() {
  SearchSettings s;
  s.metric = Metric::R2;
  s.parsimony_coefficient = 1e-5;
  s.max_length = 40;
  s.linear_scaling = true;
  s.lm_iterations = 5;
  s.lm_max_rows = 64;
  s.penalise_duplicates = true;
  s.p_crossover = 0.7;         // more mutation than gplearn keeps the population diverse
  s.p_subtree_mutation = 0.1;
  s.p_hoist_mutation = 0.05;
  s.p_point_mutation = 0.1;
  return s;
}

}  // namespace hs::regression
