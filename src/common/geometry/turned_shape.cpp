// SPDX-License-Identifier: MIT
#include "common/geometry/turned_shape.hpp"

#include <stdexcept>
#include <utility>

namespace hs::common {

TurnedToZ::TurnedToZ(std::shared_ptr<const Shape> along_x) : along_x_(std::move(along_x)) {
  if (!along_x_) throw std::invalid_argument("TurnedToZ: no shape to turn");
}

double TurnedToZ::signed_distance(const Vec3& p_m) const { return along_x_->signed_distance(original_point(p_m)); }

Box3 TurnedToZ::bounds() const {
  const Box3 b = along_x_->bounds();
  // x = -z of the original, y = y, z = x of the original.
  return {{-b.hi.z, b.lo.y, b.lo.x}, {-b.lo.z, b.hi.y, b.hi.x}};
}

}  // namespace hs::common
