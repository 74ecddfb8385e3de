// SPDX-License-Identifier: MIT
// Local fitting of an expression's numeric constants: closed-form linear scaling and Levenberg-Marquardt.
#pragma once

#include <span>

#include "regression/data_view.hpp"
#include "regression/expression.hpp"

namespace hs::regression {

/// The model is  y ~ offset + scale * f(x; c)  (offset 0, scale 1 without linear scaling).
struct ScaledModel {
  Expression tree;
  double offset = 0.0;
  double scale = 1.0;
};

/// Closed-form least-squares offset and scale for a given prediction f (Keijzer 2003, "linear scaling").
void fit_linear_scaling(std::span<const double> f, std::span<const double> y, double& offset, double& scale);

/// Levenberg-Marquardt on the sum of squared residuals over the constants c (and offset, scale when
/// `linear_scaling`), with a central-difference Jacobian. Damping (JtJ + lambda diag JtJ) is cut by 3
/// after a successful step and raised by 3 after a rejected one. Modifies `model` in place only where the
/// squared error goes down; returns the number of model evaluations spent.
long optimize_constants(ScaledModel& model, const DataView& data, std::span<const double> y, int iterations,
                        bool linear_scaling);

}  // namespace hs::regression
