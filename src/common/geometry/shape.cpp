// SPDX-License-Identifier: MIT
// Shared helpers for signed-distance shapes.
#include "common/geometry/shape.hpp"

namespace hs::common {

double wall_crossing_fraction(const Shape& shape, const Vec3& inside_point, const Vec3& outside_point, double tolerance) {
  double lo = 0.0;   // signed distance < 0 here
  double hi = 1.0;   // >= 0 here
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (shape.signed_distance(inside_point + mid * (outside_point - inside_point)) < 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace hs::common
