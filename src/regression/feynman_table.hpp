// SPDX-License-Identifier: MIT
// The AI-Feynman ground-truth tables (data/reference/feynman_ai100.csv and its 10-equation subset): equations,
// variable ranges, samples.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "regression/expression.hpp"

namespace hs::regression {

/// One row of the table: the formula as published (Python syntax) and parsed, and each variable's uniform range.
struct FeynmanEquation {
  std::string id;                   // e.g. "I.12.1"
  std::string formula;              // formula_python column, e.g. "mu*Nn"
  std::vector<std::string> names;   // variables in the order of the ranges column
  std::vector<double> lo, hi;       // sampling range of each variable
  Expression truth;
};

/// Reads the CSV (header feynman_id, formula_python, variables_with_uniform_ranges, ...; the ranges column is quoted,
/// "x1:[1,5]; x2:[1,5]"). "**" is read as "^", the identifiers pi as its value, arcsin as asin and ln as log.
/// Throws hs::common::ConfigError naming the file, the line and what is wrong.
[[nodiscard]] std::vector<FeynmanEquation> read_feynman_table(const std::filesystem::path& file);

/// n noise-free rows, each variable uniform in its range (std::mt19937_64 with `seed`): columns x[var][row], y[row].
struct FeynmanSample {
  std::vector<std::vector<double>> x;
  std::vector<double> y;
};
[[nodiscard]] FeynmanSample sample_feynman(const FeynmanEquation& eq, std::size_t n, std::uint64_t seed);

/// The symbolic judge of recovery: the same text after algebraic simplification, polynomial expansion and snapping
/// of constants to short fractions (so 0.5*(k*x*x) and 1/2*k*x^2 agree; n*T*(kb/V) and n*kb*T/V do not).
[[nodiscard]] bool symbolic_match(const Expression& model, const Expression& truth, const std::vector<std::string>& names);

}  // namespace hs::regression
