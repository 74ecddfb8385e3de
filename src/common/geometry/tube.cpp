// SPDX-License-Identifier: MIT
// A straight circular tube.
#include "common/geometry/tube.hpp"

#include <algorithm>
#include <stdexcept>

namespace hs::common {

Tube::Tube(const TubeSpec& spec) : spec_(spec) {
  const Vec3 d = spec.end_m - spec.start_m;
  length_m_ = norm(d);
  if (!(spec.radius_m > 0.0) || !(length_m_ > 0.0)) throw std::invalid_argument("Tube: radius and length must be > 0");
  axis_ = d / length_m_;
}

double Tube::signed_distance(const Vec3& p_m) const {
  const Vec3 r = p_m - spec_.start_m;
  const Vec3 radial = r - dot(r, axis_) * axis_;
  return norm(radial) - spec_.radius_m;
}

Box3 Tube::bounds() const {
  Box3 b;
  for (int i = 0; i < 3; ++i) {
    // Extent of a disc of radius R normal to the axis: R sqrt(1 - a_i^2) around each end centre.
    const double ext = spec_.radius_m * std::sqrt(std::max(0.0, 1.0 - axis_[i] * axis_[i]));
    b.lo[i] = std::min(spec_.start_m[i], spec_.end_m[i]) - ext;
    b.hi[i] = std::max(spec_.start_m[i], spec_.end_m[i]) + ext;
  }
  return b;
}

}  // namespace hs::common
