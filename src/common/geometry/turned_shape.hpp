// SPDX-License-Identifier: MIT
// A shape built along +x, turned so that it runs along +z: the built-in shapes all run along +x, while the distributed
// CFD-DEM cuts its grid into z-slabs and lets cells in through inlets that face along z.
#pragma once

#include <memory>

#include "common/geometry/shape.hpp"

namespace hs::common {

/// The shape turned by -90 deg about y: its +x becomes +z, its +z becomes -x, y stays. A point p of the turned shape
/// is the point (p.z, p.y, -p.x) of the original.
class TurnedToZ final : public Shape {
 public:
  explicit TurnedToZ(std::shared_ptr<const Shape> along_x);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;
  [[nodiscard]] const Shape& original() const { return *along_x_; }

  /// The original shape's point q in the turned frame, and back.
  [[nodiscard]] static Vec3 turned(const Vec3& q) { return {-q.z, q.y, q.x}; }
  [[nodiscard]] static Vec3 original_point(const Vec3& p) { return {p.z, p.y, -p.x}; }

 private:
  std::shared_ptr<const Shape> along_x_;
};

}  // namespace hs::common
