// SPDX-License-Identifier: MIT
// A learned drag closure: the drag coefficient C_d from a closure file (kind = "drag").
#pragma once

#include <filesystem>
#include <memory>

#include "closures/drag_closure.hpp"
#include "closures/learned_formula.hpp"

namespace hs::closures {

class ExpressionDrag final : public DragClosure {
 public:
  /// Loads and compiles the closure file; ConfigError for a bad file or a kind other than "drag".
  explicit ExpressionDrag(const std::filesystem::path& file) : ExpressionDrag(std::make_unique<LearnedFormula>(file, "drag")) {}
  [[nodiscard]] const ClosureFile& file() const { return formula_->file(); }

 private:
  explicit ExpressionDrag(std::unique_ptr<LearnedFormula> f)
      : DragClosure(f->file().name, f->validity()), formula_(std::move(f)) {}
  [[nodiscard]] double compute_drag_coefficient(const DragInputs& in) const override { return (*formula_)(in); }

  std::unique_ptr<LearnedFormula> formula_;
};

}  // namespace hs::closures
