// SPDX-License-Identifier: MIT
// A parent tube splitting into two daughter tubes in one plane: the bifurcated microchannel of the seed
// paper, section 4.3 (after Stathoulopoulos et al. 2024), at any angle.
#pragma once

#include <array>

#include "common/geometry/shape.hpp"

namespace hs::common {

/// The parent runs along +x into the junction; each daughter leaves the junction in the xy-plane at its
/// angle from +x (degrees, counter-clockwise). A symmetric Y of opening alpha: {+alpha/2, -alpha/2};
/// a side branch off a straight channel (Stathoulopoulos' "outlet" and "daughter" branches): {0, alpha}.
struct BifurcationSpec {
  Vec3 junction_m;
  double parent_radius_m;
  double parent_length_m;
  std::array<double, 2> daughter_radius_m;
  std::array<double, 2> daughter_length_m;
  std::array<double, 2> daughter_angle_deg;
};

class Bifurcation final : public Shape {
 public:
  explicit Bifurcation(const BifurcationSpec& spec);
  /// Union (minimum) of three half-infinite tubes and a ball of the parent radius that rounds the junction;
  /// exact outside the junction region, sign exact everywhere. The far ends are open (inlet and outlets).
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;
  /// Unit direction of daughter i (0 or 1), pointing away from the junction.
  [[nodiscard]] Vec3 daughter_direction(int i) const { return directions_[static_cast<std::size_t>(i) + 1]; }
  [[nodiscard]] const BifurcationSpec& spec() const { return spec_; }

 private:
  BifurcationSpec spec_;
  std::array<Vec3, 3> directions_;   // parent (pointing upstream, -x), daughter 0, daughter 1
  std::array<double, 3> radii_;
  std::array<double, 3> lengths_;
};

}  // namespace hs::common
