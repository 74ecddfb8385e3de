// SPDX-License-Identifier: MIT
// Blood's wide-tube bulk viscosity (Pries et al. 1992 at D -> infinity), the "pries_bulk" suspension law.
#include "unresolved/coupling/bulk_blood_viscosity.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::unresolved {

double bulk_blood_relative_viscosity(double phi) {
  if (!(phi >= 0.0 && phi < 1.0)) throw std::invalid_argument("bulk blood viscosity: phi must be in [0, 1)");
  constexpr double c = -0.8;    // Pries 1992 shape exponent C(D) for D -> infinity
  constexpr double mu45 = 3.2;  // Pries 1992 mu_0.45(D) for D -> infinity
  return 1.0 + (mu45 - 1.0) * (std::pow(1.0 - phi, c) - 1.0) / (std::pow(0.55, c) - 1.0);
}

}  // namespace hs::unresolved
