// SPDX-License-Identifier: MIT
// Loading and evaluating learned closure formulas.
#include "closures/learned_formula.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::closures {

LearnedFormula::LearnedFormula(const std::filesystem::path& file, const std::string& expected_kind, OutsideValidity outside)
    : file_(ClosureFile::load(file)), outside_(outside) {
  if (file_.kind != expected_kind) {
    throw hs::common::ConfigError(fmt::format("{}: kind = \"{}\": a {} closure is needed here", file.string(),
                                              file_.kind, expected_kind));
  }
  for (const auto& name : file_.variables) fields_.push_back(find_input(name)->field);
  program_ = hs::regression::CompiledProgram(file_.parsed());
}

double LearnedFormula::operator()(const ClosureInputs& in) const {
  std::array<double, input_variables.size()> x{};
  for (std::size_t j = 0; j < fields_.size(); ++j) x[j] = input(in, j);
  return program_.evaluate_point(x.data());
}

ClosureInputs LearnedFormula::clamped(const ClosureInputs& in) const {
  ClosureInputs out = in;
  for (std::size_t j = 0; j < fields_.size(); ++j) out.*fields_[j] = input(in, j);
  return out;
}

double LearnedFormula::input(const ClosureInputs& in, std::size_t j) const {
  const double v = in.*fields_[j];
  return outside_ == OutsideValidity::clamp ? std::clamp(v, file_.validity[j].lo, file_.validity[j].hi) : v;
}

Validity LearnedFormula::validity() const {
  Validity v;
  for (std::size_t j = 0; j < file_.variables.size(); ++j) v.emplace_back(*find_input(file_.variables[j]), file_.validity[j]);
  return v;
}

}  // namespace hs::closures
