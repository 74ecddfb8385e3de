// SPDX-License-Identifier: MIT
// A learned deformation closure: the deformation index DI from a closure file (kind = "deformation").
#pragma once

#include <filesystem>
#include <memory>

#include "closures/deformation_closure.hpp"
#include "closures/closure_registry.hpp"
#include "closures/learned_formula.hpp"

namespace hs::closures {

class ExpressionDeformation final : public DeformationClosure {
 public:
  /// Loads and compiles the closure file; ConfigError for a bad file or a kind other than "deformation".
  explicit ExpressionDeformation(const std::filesystem::path& file, OutsideValidity outside = OutsideValidity::clamp)
      : ExpressionDeformation(std::make_unique<LearnedFormula>(file, "deformation", outside)) {}
  [[nodiscard]] const ClosureFile& file() const { return formula_->file(); }

 private:
  explicit ExpressionDeformation(std::unique_ptr<LearnedFormula> f)
      : DeformationClosure(f->file().name, f->validity()), formula_(std::move(f)) {}
  [[nodiscard]] double compute_deformation_index(const DeformationInputs& in) const override { return (*formula_)(in); }

  std::unique_ptr<LearnedFormula> formula_;
};

}  // namespace hs::closures
