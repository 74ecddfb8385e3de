// SPDX-License-Identifier: MIT
// A closure file compiled to the fast evaluator, reading its variables straight from ClosureInputs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "closures/closure.hpp"
#include "closures/closure_file.hpp"
#include "regression/compiled_program.hpp"

namespace hs::closures {

class LearnedFormula {
 public:
  /// Loads `file` and checks that its kind is `expected_kind` (ConfigError otherwise, and for every reason
  /// ClosureFile::load gives).
  LearnedFormula(const std::filesystem::path& file, const std::string& expected_kind);

  /// The expression at `in` (protected semantics: never NaN/inf for finite inputs).
  [[nodiscard]] double operator()(const ClosureInputs& in) const;
  [[nodiscard]] const ClosureFile& file() const { return file_; }
  [[nodiscard]] Validity validity() const;

 private:
  ClosureFile file_;
  hs::regression::CompiledProgram program_;
  std::vector<double ClosureInputs::*> fields_;   // feature j of the program
};

}  // namespace hs::closures
