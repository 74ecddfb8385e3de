// SPDX-License-Identifier: MIT
// An axis-aligned box of fluid (a periodic cube, a rectangular duct section).
#pragma once

#include "common/geometry/shape.hpp"

namespace hs::common {

class BoxShape final : public Shape {
 public:
  explicit BoxShape(const Box3& box);
  /// Exact Euclidean signed distance to the box surface.
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override { return box_; }

 private:
  Box3 box_;
};

}  // namespace hs::common
