// SPDX-License-Identifier: MIT
// A learned drag closure: the drag coefficient C_d from a closure file (kind = "drag").
#pragma once

#include <filesystem>
#include <memory>

#include "closures/drag_closure.hpp"
#include "closures/closure_registry.hpp"
#include "closures/learned_formula.hpp"

namespace hs::closures {

class ExpressionDrag final : public DragClosure {
 public:
  /// Loads and compiles the closure file; ConfigError for a bad file or a kind other than "drag".
  explicit ExpressionDrag(const std::filesystem::path& file, OutsideValidity outside = OutsideValidity::clamp)
      : ExpressionDrag(std::make_unique<LearnedFormula>(file, "drag", outside)) {}
  [[nodiscard]] const ClosureFile& file() const { return formula_->file(); }

 private:
  explicit ExpressionDrag(std::unique_ptr<LearnedFormula> f)
      : DragClosure(f->file().name, f->validity()), formula_(std::move(f)) {}
  /// Clamped outside the box, the correction C_d Re_p / 24 keeps its edge value (so a Stokes-like drag stays linear
  /// in the slip below the box instead of vanishing with Re_p), and C_d is the one that gives that correction.
  [[nodiscard]] double compute_drag_coefficient(const DragInputs& in) const override {
    const DragInputs c = formula_->clamped(in);
    const double cd = (*formula_)(c);
    return c.re_p == in.re_p || !(in.re_p > 0.0) ? cd : cd * c.re_p / in.re_p;
  }

  std::unique_ptr<LearnedFormula> formula_;
};

}  // namespace hs::closures
