// SPDX-License-Identifier: MIT
// A closure file compiled to the fast evaluator, reading its variables straight from ClosureInputs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "closures/closure.hpp"
#include "closures/closure_file.hpp"
#include "closures/closure_registry.hpp"
#include "regression/compiled_program.hpp"

namespace hs::closures {

class LearnedFormula {
 public:
  /// Loads `file` and checks that its kind is `expected_kind` (ConfigError otherwise, and for every reason
  /// ClosureFile::load gives).
  LearnedFormula(const std::filesystem::path& file, const std::string& expected_kind,
                 OutsideValidity outside = OutsideValidity::clamp);

  /// The expression at `in`, its inputs clamped to the validity box unless `outside` is extrapolate
  /// (protected semantics: never NaN/inf for finite inputs).
  [[nodiscard]] double operator()(const ClosureInputs& in) const;
  /// `in` with the formula's variables clamped to the validity box (unchanged when `outside` is extrapolate).
  [[nodiscard]] ClosureInputs clamped(const ClosureInputs& in) const;
  [[nodiscard]] const ClosureFile& file() const { return file_; }
  [[nodiscard]] OutsideValidity outside() const { return outside_; }
  [[nodiscard]] Validity validity() const;

 private:
  /// Variable j of the formula at `in`, clamped to its validity interval unless `outside_` is extrapolate.
  [[nodiscard]] double input(const ClosureInputs& in, std::size_t j) const;

  ClosureFile file_;
  hs::regression::CompiledProgram program_;
  std::vector<double ClosureInputs::*> fields_;   // feature j of the program
  OutsideValidity outside_;
};

}  // namespace hs::closures
