// SPDX-License-Identifier: MIT
// A planar channel with a smooth constriction.
#include "common/geometry/stenosed_channel.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::common {

StenosedChannel::StenosedChannel(const StenosedChannelSpec& spec)
    : spec_(spec), profile_{0.5 * spec.height_m, 0.5 * spec.throat_height_m, spec.constriction_length_m} {
  profile_.check();
  if (!(spec.x_end_m > spec.x_start_m) || !(spec.z_hi_m > spec.z_lo_m)) {
    throw std::invalid_argument("StenosedChannel: x and z extents must be positive");
  }
}

double StenosedChannel::signed_distance(const Vec3& p_m) const {
  const double s = p_m.x - spec_.constriction_centre_x_m;
  const double slope = profile_.slope(s);
  return (std::abs(p_m.y - spec_.centre_y_m) - profile_.half_width(s)) / std::sqrt(1.0 + slope * slope);
}

Box3 StenosedChannel::bounds() const {
  const double h = 0.5 * spec_.height_m;
  return {{spec_.x_start_m, spec_.centre_y_m - h, spec_.z_lo_m}, {spec_.x_end_m, spec_.centre_y_m + h, spec_.z_hi_m}};
}

}  // namespace hs::common
