// SPDX-License-Identifier: MIT
// A planar channel (two parallel walls) with a smooth constriction: the stenosis of the seed paper,
// section 3.2 (Hsieh 2020) and, ten times larger, section 4.4.
#pragma once

#include "common/geometry/constriction_profile.hpp"
#include "common/geometry/shape.hpp"

namespace hs::common {

/// Flow along x, walls normal to y at y = centre_y +- h(x), unbounded in z (periodic or closed by a box).
struct StenosedChannelSpec {
  double x_start_m;
  double x_end_m;
  double centre_y_m;
  double height_m;               // open wall-to-wall distance
  double throat_height_m;        // wall-to-wall distance at the throat
  double constriction_length_m;
  double constriction_centre_x_m;
  double z_lo_m;                 // extent in z, for bounds() only
  double z_hi_m;
};

class StenosedChannel final : public Shape {
 public:
  explicit StenosedChannel(const StenosedChannelSpec& spec);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;

 private:
  StenosedChannelSpec spec_;
  ConstrictionProfile profile_;
};

}  // namespace hs::common
