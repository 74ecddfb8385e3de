// SPDX-License-Identifier: MIT
// An axis-aligned box of fluid.
#include "common/geometry/box_shape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hs::common {

BoxShape::BoxShape(const Box3& box) : box_(box) {
  for (int i = 0; i < 3; ++i) {
    if (!(box.hi[i] > box.lo[i])) throw std::invalid_argument("BoxShape: every hi must exceed lo");
  }
}

double BoxShape::signed_distance(const Vec3& p_m) const {
  Vec3 outside;
  double inside = -HUGE_VAL;
  for (int i = 0; i < 3; ++i) {
    const double centre = 0.5 * (box_.lo[i] + box_.hi[i]);
    const double q = std::abs(p_m[i] - centre) - 0.5 * (box_.hi[i] - box_.lo[i]);
    outside[i] = std::max(q, 0.0);
    inside = std::max(inside, q);
  }
  return norm(outside) + std::min(inside, 0.0);
}

}  // namespace hs::common
