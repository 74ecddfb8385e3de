// SPDX-License-Identifier: MIT
// The in-vitro blood rheology laws of Pries et al. 1992.
#include "analysis/pries1992.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::analysis {
namespace {

double fahraeus_x(double d) { return 1.0 + 1.7 * std::exp(-0.35 * d) - 0.6 * std::exp(-0.01 * d); }

void check(double diameter_um, double hematocrit) {
  if (!(diameter_um > 0.0) || !(hematocrit >= 0.0 && hematocrit < 1.0)) {
    throw std::invalid_argument("Pries 1992: need D > 0 um and 0 <= hematocrit < 1");
  }
}

}  // namespace

double fahraeus_ratio(double diameter_um, double discharge_hematocrit) {
  check(diameter_um, discharge_hematocrit);
  return discharge_hematocrit + (1.0 - discharge_hematocrit) * fahraeus_x(diameter_um);
}

double discharge_from_tube_hematocrit(double diameter_um, double tube_hematocrit) {
  check(diameter_um, tube_hematocrit);
  const double x = fahraeus_x(diameter_um);
  const double a = 1.0 - x;
  if (std::abs(a) < 1e-14) return tube_hematocrit / x;   // the quadratic degenerates to a line
  // Root of a H^2 + x H - Ht_T = 0 that is positive: written without cancellation.
  const double disc = std::sqrt(x * x + 4.0 * a * tube_hematocrit);
  return 2.0 * tube_hematocrit / (x + disc);
}

double relative_viscosity_at_045(double d) {
  if (!(d > 0.0)) throw std::invalid_argument("Pries 1992: D must be > 0 um");
  return 220.0 * std::exp(-1.3 * d) + 3.2 - 2.44 * std::exp(-0.06 * std::pow(d, 0.645));
}

double viscosity_shape_exponent(double d) {
  if (!(d > 0.0)) throw std::invalid_argument("Pries 1992: D must be > 0 um");
  const double f = 1.0 / (1.0 + 1e-11 * std::pow(d, 12.0));
  return (0.8 + std::exp(-0.075 * d)) * (-1.0 + f) + f;
}

double relative_apparent_viscosity(double diameter_um, double discharge_hematocrit) {
  check(diameter_um, discharge_hematocrit);
  const double c = viscosity_shape_exponent(diameter_um);
  const double mu45 = relative_viscosity_at_045(diameter_um);
  return 1.0 + (mu45 - 1.0) * (std::pow(1.0 - discharge_hematocrit, c) - 1.0) / (std::pow(0.55, c) - 1.0);
}

}  // namespace hs::analysis
