// SPDX-License-Identifier: MIT
// A circular tube with a smooth axisymmetric constriction (a stenosed vessel).
#pragma once

#include "common/geometry/constriction_profile.hpp"
#include "common/geometry/shape.hpp"

namespace hs::common {

struct StenosedTubeSpec {
  Vec3 start_m;                  // centre of the inlet face
  Vec3 end_m;                    // centre of the outlet face
  double radius_m;               // open radius
  double throat_radius_m;        // radius at the narrowest section
  double constriction_length_m;  // axial length of the narrowing
  double constriction_centre_m;  // distance of the throat from start_m along the axis
};

class StenosedTube final : public Shape {
 public:
  explicit StenosedTube(const StenosedTubeSpec& spec);
  /// First-order distance (r(s) - rho)/sqrt(1 + r'(s)^2): exact in the straight parts, sign exact everywhere.
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;
  [[nodiscard]] const StenosedTubeSpec& spec() const { return spec_; }
  /// The narrowing in the tube's own coordinate s (distance along the axis from start_m, throat at
  /// constriction_centre_m): the wall radius is profile().half_width(s - constriction_centre_m).
  [[nodiscard]] const ConstrictionProfile& profile() const { return profile_; }
  /// Wall radius at distance s_m along the axis from start_m.
  [[nodiscard]] double radius_at(double s_m) const { return profile_.half_width(s_m - spec_.constriction_centre_m); }

 private:
  StenosedTubeSpec spec_;
  ConstrictionProfile profile_;
  Vec3 axis_;
  double length_m_;
};

}  // namespace hs::common
