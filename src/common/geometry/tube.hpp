// SPDX-License-Identifier: MIT
// A straight circular tube (cylinder) along an axis: the channel of the campaign and the Pries validation.
#pragma once

#include "common/geometry/shape.hpp"

namespace hs::common {

struct TubeSpec {
  Vec3 start_m;      // centre of the inlet face
  Vec3 end_m;        // centre of the outlet face
  double radius_m;
};

/// The fluid inside a cylinder. The end faces are open for periodic or inlet/outlet use: the signed
/// distance is the radial one only, clipped to the bounds along the axis by bounds().
class Tube final : public Shape {
 public:
  explicit Tube(const TubeSpec& spec);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;
  [[nodiscard]] const TubeSpec& spec() const { return spec_; }

 private:
  TubeSpec spec_;
  Vec3 axis_;        // unit vector start -> end
  double length_m_;
};

}  // namespace hs::common
