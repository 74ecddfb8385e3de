// SPDX-License-Identifier: MIT
// The smooth (cosine) narrowing shared by the stenosed tube and channel.
#include "common/geometry/constriction_profile.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hs::common {

double ConstrictionProfile::half_width(double s_m) const {
  if (std::abs(s_m) >= 0.5 * length_m) return open_half_width_m;
  const double depth = open_half_width_m - throat_half_width_m;
  return open_half_width_m - 0.5 * depth * (1.0 + std::cos(2.0 * std::numbers::pi * s_m / length_m));
}

double ConstrictionProfile::slope(double s_m) const {
  if (std::abs(s_m) >= 0.5 * length_m) return 0.0;
  const double depth = open_half_width_m - throat_half_width_m;
  const double k = 2.0 * std::numbers::pi / length_m;
  return 0.5 * depth * k * std::sin(k * s_m);
}

void ConstrictionProfile::check() const {
  if (!(throat_half_width_m > 0.0) || !(throat_half_width_m <= open_half_width_m) || !(length_m > 0.0)) {
    throw std::invalid_argument("constriction: need 0 < throat <= open width and length > 0");
  }
}

}  // namespace hs::common
