// SPDX-License-Identifier: MIT
// A learned lift closure: the lift coefficient C_l from a closure file (kind = "lift").
#pragma once

#include <algorithm>
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
      : LiftClosure(f->file().name, f->validity()), formula_(std::move(f)) {
    const auto& vars = formula_->file().variables;
    for (std::size_t j = 0; j < vars.size(); ++j) {
      if (vars[j] == "gamma_plus" && formula_->outside() == OutsideValidity::clamp) fade_below_ = formula_->file().validity[j].lo;
    }
  }
  /// Clamped below its box in gamma+, C_l fades linearly to zero with gamma+: the lift is odd in the radial position
  /// and vanishes on a tube's axis, where gamma+ (linear in r in Poiseuille flow) does too. Holding the edge value
  /// instead keeps a finite inward lift on the axis and piles the cells up there.
  [[nodiscard]] double compute_lift_coefficient(const LiftInputs& in) const override {
    const double cl = (*formula_)(in);
    return in.gamma_plus < fade_below_ ? cl * std::max(in.gamma_plus, 0.0) / fade_below_ : cl;
  }

  std::unique_ptr<LearnedFormula> formula_;
  double fade_below_ = 0.0;   // gamma+ below which C_l fades to zero (the box's lower edge; 0: no fading)
};

}  // namespace hs::closures
