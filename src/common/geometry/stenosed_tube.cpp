// SPDX-License-Identifier: MIT
// A circular tube with a smooth axisymmetric constriction.
#include "common/geometry/stenosed_tube.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/geometry/tube.hpp"

namespace hs::common {

StenosedTube::StenosedTube(const StenosedTubeSpec& spec)
    : spec_(spec), profile_{spec.radius_m, spec.throat_radius_m, spec.constriction_length_m} {
  profile_.check();
  const Vec3 d = spec.end_m - spec.start_m;
  length_m_ = norm(d);
  if (!(length_m_ > 0.0)) throw std::invalid_argument("StenosedTube: start and end must differ");
  axis_ = d / length_m_;
}

double StenosedTube::signed_distance(const Vec3& p_m) const {
  const Vec3 r = p_m - spec_.start_m;
  const double s = dot(r, axis_);
  const double rho = norm(r - s * axis_);
  const double local = s - spec_.constriction_centre_m;
  const double slope = profile_.slope(local);
  return (rho - profile_.half_width(local)) / std::sqrt(1.0 + slope * slope);
}

Box3 StenosedTube::bounds() const {
  return Tube({.start_m = spec_.start_m, .end_m = spec_.end_m, .radius_m = spec_.radius_m}).bounds();
}

}  // namespace hs::common
