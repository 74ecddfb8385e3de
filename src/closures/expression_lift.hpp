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
      const auto input = find_input(vars[j]);
      const bool shear = vars[j] == "gamma_plus" || vars[j] == "re_shear" || vars[j] == "shear_ratio";
      if (shear && input && formula_->outside() == OutsideValidity::clamp) {
        shear_ = input->field;
        fade_below_ = formula_->file().validity[j].lo;
      }
    }
  }
  /// Clamped below its box in its shear variable (gamma+, Re_shear or the shear ratio, all proportional to the shear
  /// rate), C_l fades linearly to zero with it: the lift is odd in the radial position and vanishes on a tube's axis,
  /// where the shear rate (linear in r in Poiseuille flow) does too. Holding the edge value instead keeps a finite inward lift on the
  /// axis and piles the cells up there.
  [[nodiscard]] double compute_lift_coefficient(const LiftInputs& in) const override {
    const double cl = (*formula_)(in);
    if (shear_ == nullptr) return cl;
    const double shear = in.*shear_;
    return shear < fade_below_ ? cl * std::max(shear, 0.0) / fade_below_ : cl;
  }

  std::unique_ptr<LearnedFormula> formula_;
  double ClosureInputs::*shear_ = nullptr;   // the shear variable among the inputs (nullptr: no fading)
  double fade_below_ = 0.0;                  // below it C_l fades to zero (the box's lower edge)
};

}  // namespace hs::closures
