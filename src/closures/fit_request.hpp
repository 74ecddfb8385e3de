// SPDX-License-Identifier: MIT
// A fit file (FIT.toml) for `hemoscale fit`, read strictly into typed settings.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "regression/model_selection.hpp"
#include "regression/search_settings.hpp"

namespace hs::closures {

/// FIT.toml:
///   [data]    file = "dataset.csv" (relative to FIT.toml), target = "cd", features = ["di", "re_p"],
///             test_fraction = 0.2, folds = 5
///   [closure] name = "cd_di_rep", kind = "drag" | "lift" | "deformation" | "generic", output = "C_d",
///             reference_velocity = "slip" | "flow" (lift only: the velocity the target C_l was normalised with)
///   [variables] optional definitions per feature (closure inputs have built-in ones)
///   [search]  engine = "full" | "gplearn" (which defaults), then any of: functions, population_size,
///             generations, tournament_size, const_range, init_depth, metric, parsimony_coefficient
///             (or "auto"), p_crossover, p_subtree_mutation, p_hoist_mutation, p_point_mutation,
///             p_point_replace, stopping_criteria, max_length, linear_scaling, lm_iterations, lm_max_rows,
///             max_seconds, selection_tolerance, restarts, lexicase, penalise_duplicates, seed, threads
///   [units]   optional SI unit per feature and for the target, e.g. d = "m", mu = "Pa*s", F = "N" ("1" for a
///             dimensionless column); closure inputs and the drag/lift/deformation outputs are dimensionless and
///             need none. With every unit known the search keeps to dimensionally consistent formulas
///             ([search] dimensional_constraints = false turns that off) and the closure file records them.
///   [output]  plot = true
struct FitRequest {
  std::filesystem::path fit_file;
  std::filesystem::path dataset;
  std::string target;
  std::vector<std::string> features;
  /// [data.derived]: features computed per row from the dataset's columns, name -> expression (infix, as in closure
  /// files), e.g. shear_ratio = "gamma_plus * 0.0501 / re_p" (gammadot d_p / u from gammadot R_c^2 / nu in one tube).
  std::vector<std::pair<std::string, std::string>> derived;
  std::vector<std::string> definitions;   // one per feature
  std::vector<std::string> feature_units; // one per feature ("" = not given)
  std::string target_unit;                // "" = not given
  std::string name, kind, output;
  std::string reference_velocity = "slip";   // lift only
  hs::regression::SearchSettings search;
  hs::regression::ValidationSettings validation;
  bool plot = true;
};

/// What `hemoscale fit` searches with when FIT.toml's [search] holds no budget key (population_size, generations,
/// restarts, stopping_criteria, max_seconds) for `engine` ("full" or "gplearn"): every fit default in one place,
/// so that `hemoscale bench feynman` measures exactly what a user gets. Seed 0, every core.
[[nodiscard]] hs::regression::SearchSettings default_fit_search(std::string_view engine = "full");

/// Throws hs::common::ConfigError (file, key, value, what is allowed) for any bad or unknown key.
[[nodiscard]] FitRequest read_fit_request(const std::filesystem::path& file);

}  // namespace hs::closures
