// SPDX-License-Identifier: MIT
// A learned closure on disk (DESIGN.md "Inputs and outputs", STYLE R12): infix expression, variables with
// definitions, validity range, fit metrics, Pareto front and provenance, read strictly and written back.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <string>
#include <vector>

#include "closures/closure_inputs.hpp"
#include "regression/expression.hpp"

namespace hs::closures {

struct ParetoPoint {
  std::size_t complexity = 0;
  double loss = 0.0;      // training loss of the search metric
  double cv_loss = 0.0;   // cross-validated loss (= loss when no CV)
  std::string expression;
};

struct ClosureFile {
  std::string name;
  std::string kind;                         // drag | lift | deformation | generic
  std::string output;                       // what the expression gives: C_d, C_l, DI, or a column name
  std::string reference_velocity = "slip";  // lift only: the velocity C_l was normalised with, "slip" or "flow"
                                            // (docs/coefficients.md "Why C_l uses u(r)")
  std::string expression;                   // infix; round-trips through regression::parse_infix
  std::vector<std::string> variables;       // expression variable names (feature order)
  std::vector<std::string> definitions;     // one per variable
  std::vector<Interval> validity;           // one per variable: min/max of the training inputs
  std::map<std::string, std::string> units; // [units]: SI unit of the output and of each variable ("1":
                                            // dimensionless); empty when the fit was given none
  std::map<std::string, double> fit;        // r2_train, r2_cv, r2_test, rmse_*, mae_*, n_train, ...
  /// [uncertainty]: the expression's constants (prefix order) refitted on bootstrap resamples of the training rows,
  /// one set per replicate, and the residual rmse (cross-validated) of new data around the formula; empty when the
  /// closure was fitted without them.
  std::vector<std::vector<double>> bootstrap_constants;
  double residual_rmse = 0.0;
  std::vector<ParetoPoint> pareto;
  std::string dataset;                      // provenance
  std::string dataset_sha256;
  std::int64_t seed = 0;
  std::int64_t threads = 1;
  std::string hemoscale_version;
  std::string git_commit;

  /// Reads and checks a closure file. Throws hs::common::ConfigError naming file and key for: malformed TOML,
  /// a missing key or section, an unknown key, a variable that is not a closure input (kinds other than
  /// generic), an expression that does not parse or names an undeclared variable, a variable without a
  /// validity range, a range with lo > hi, or a Pareto front whose lists differ in length.
  [[nodiscard]] static ClosureFile load(const std::filesystem::path& file);
  /// Writes the file (atomically); load(write(c)) == c up to the shortest round-trip printing of numbers.
  void write(const std::filesystem::path& file) const;
  /// The parsed expression (feature j = variables[j]).
  [[nodiscard]] hs::regression::Expression parsed() const;
  /// The 95% prediction interval at `inputs` (one value per variable): the 2.5 and 97.5 percentiles of the formula
  /// over the bootstrap constants, each side widened in quadrature by 1.96 residual_rmse (new data scatter around
  /// the formula, not only its constants do). nullopt without [uncertainty].
  [[nodiscard]] std::optional<std::pair<double, double>> prediction_interval(std::span<const double> inputs) const;
};

}  // namespace hs::closures
