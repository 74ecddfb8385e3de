// SPDX-License-Identifier: MIT
// A learned lift closure: the lift coefficient C_l from a closure file (kind = "lift").
#pragma once

#include <filesystem>
#include <memory>

#include "closures/lift_closure.hpp"
#include "closures/closure_registry.hpp"
#include "closures/learned_formula.hpp"

namespace hs::closures {

class ExpressionLift final : public LiftClosure {
 public:
  /// Loads and compiles the closure file; ConfigError for a bad file or a kind other than "lift".
  explicit ExpressionLift(const std::filesystem::path& file, OutsideValidity outside = OutsideValidity::clamp)
      : ExpressionLift(std::make_unique<LearnedFormula>(file, "lift", outside)) {}
  [[nodiscard]] const ClosureFile& file() const { return formula_->file(); }
  [[nodiscard]] LiftVelocity reference_velocity() const override {
    return file().reference_velocity == "flow" ? LiftVelocity::flow : LiftVelocity::slip;
  }

 private:
  explicit ExpressionLift(std::unique_ptr<LearnedFormula> f)
      : LiftClosure(f->file().name, f->validity()), formula_(std::move(f)) {}
  [[nodiscard]] double compute_lift_coefficient(const LiftInputs& in) const override { return (*formula_)(in); }

  std::unique_ptr<LearnedFormula> formula_;
};

}  // namespace hs::closures
