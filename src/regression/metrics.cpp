// SPDX-License-Identifier: MIT
// Fitness metrics over a target and a prediction vector.
#include "regression/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hs::regression {

Metric metric_from_name(std::string_view name) {
  if (name == "mae") return Metric::Mae;
  if (name == "mse") return Metric::Mse;
  if (name == "rmse") return Metric::Rmse;
  if (name == "r2") return Metric::R2;
  throw std::invalid_argument("unknown metric \"" + std::string(name) + "\" (allowed: mae, mse, rmse, r2)");
}

std::string_view metric_name(Metric m) {
  switch (m) {
    case Metric::Mae: return "mae";
    case Metric::Mse: return "mse";
    case Metric::Rmse: return "rmse";
    case Metric::R2: return "r2";
  }
  return "";
}

double mean_absolute_error(std::span<const double> y, std::span<const double> p) {
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) s += std::abs(y[i] - p[i]);
  return y.empty() ? 0.0 : s / static_cast<double>(y.size());
}

double mean_squared_error(std::span<const double> y, std::span<const double> p) {
  double s = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) s += (y[i] - p[i]) * (y[i] - p[i]);
  return y.empty() ? 0.0 : s / static_cast<double>(y.size());
}

double root_mean_squared_error(std::span<const double> y, std::span<const double> p) {
  return std::sqrt(mean_squared_error(y, p));
}

double r_squared(std::span<const double> y, std::span<const double> p) {
  if (y.empty()) return 0.0;
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double ss_tot = 0.0;
  double ss_res = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ss_tot += (y[i] - mean) * (y[i] - mean);
    ss_res += (y[i] - p[i]) * (y[i] - p[i]);
  }
  return 1.0 - ss_res / std::max(ss_tot, std::numeric_limits<double>::min());
}

double loss(Metric m, std::span<const double> y, std::span<const double> p) {
  for (double v : p) {
    if (!std::isfinite(v)) return std::numeric_limits<double>::infinity();
  }
  double l = 0.0;
  switch (m) {
    case Metric::Mae: l = mean_absolute_error(y, p); break;
    case Metric::Mse: l = mean_squared_error(y, p); break;
    case Metric::Rmse: l = root_mean_squared_error(y, p); break;
    case Metric::R2: l = 1.0 - r_squared(y, p); break;
  }
  return std::isfinite(l) ? l : std::numeric_limits<double>::infinity();
}

}  // namespace hs::regression
