// SPDX-License-Identifier: MIT
// Fitness metrics (gplearn fitness.py: MAE, MSE, RMSE; plus R^2) and the loss the search minimises.
#pragma once

#include <span>
#include <string_view>

namespace hs::regression {

enum class Metric { Mae, Mse, Rmse, R2 };

[[nodiscard]] Metric metric_from_name(std::string_view name);   // "mae", "mse", "rmse", "r2"; throws otherwise
[[nodiscard]] std::string_view metric_name(Metric m);

[[nodiscard]] double mean_absolute_error(std::span<const double> y, std::span<const double> p);
[[nodiscard]] double mean_squared_error(std::span<const double> y, std::span<const double> p);
[[nodiscard]] double root_mean_squared_error(std::span<const double> y, std::span<const double> p);
/// Coefficient of determination 1 - SS_res / SS_tot; 1 - SS_res/tiny when y is constant.
[[nodiscard]] double r_squared(std::span<const double> y, std::span<const double> p);

/// The quantity minimised: the metric itself for MAE/MSE/RMSE, 1 - R^2 for R^2. A prediction that is not
/// finite everywhere gets +inf (never selected).
[[nodiscard]] double loss(Metric m, std::span<const double> y, std::span<const double> p);

}  // namespace hs::regression
