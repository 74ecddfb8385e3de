// SPDX-License-Identifier: MIT
// The `hemoscale fit` workflow: dataset -> search -> closure file, predictions, Pareto front, report.
#pragma once

#include <filesystem>

#include "closures/closure_file.hpp"
#include "closures/fit_request.hpp"

namespace hs::closures {

/// Runs the search described by `request` on its dataset and writes into `out_dir`:
///   <name>.toml            the closure file (expression, variables, validity = min/max of training inputs,
///                          train/CV/test errors, Pareto front, dataset sha256, seed)
///   <name>.reference.csv   the closure evaluated on its test rows (STYLE R9 reference table)
///   predictions.csv        every row: is_test, target, prediction, features
///   pareto.csv             complexity, training loss, CV loss of the front
///   summary.json           metrics and provenance
/// ConfigError for a dataset that cannot be read or lacks a column; returns the closure as written.
ClosureFile run_fit(const FitRequest& request, const std::filesystem::path& out_dir, bool quiet = false);

/// Runs tools/plot_fit.py on a fit folder (report.png) when /usr/bin/python3 and the script exist.
/// Returns false (and writes nothing) otherwise.
bool render_fit_report(const std::filesystem::path& out_dir);

}  // namespace hs::closures
