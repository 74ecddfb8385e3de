// SPDX-License-Identifier: MIT
// A region of space given by its signed distance: the fluid domains of both stages (tube, stenosis,
// bifurcation, STL) are Shapes, so the resolved and the unresolved solver see the same walls.
#pragma once

#include "common/vec3.hpp"

namespace hs::common {

/// Axis-aligned bounding box in metres.
struct Box3 {
  Vec3 lo;
  Vec3 hi;
};

/// Convention: signed_distance(p) < 0 inside the region (the fluid), > 0 outside (the wall material),
/// 0 on the wall. |signed_distance| is the Euclidean distance to the wall where the shape can give it
/// exactly, and otherwise a lower bound that is exact at the wall (enough for bisection along links).
class Shape {
 public:
  virtual ~Shape() = default;
  [[nodiscard]] virtual double signed_distance(const Vec3& p_m) const = 0;
  /// A box containing the whole region.
  [[nodiscard]] virtual Box3 bounds() const = 0;

  [[nodiscard]] bool inside(const Vec3& p_m) const { return signed_distance(p_m) < 0.0; }
};

/// Fraction q in (0, 1] along the segment from `inside_point` (in the region) to `outside_point` where the
/// wall is crossed, found by bisection on the signed distance to `tolerance` (fraction of the segment).
double wall_crossing_fraction(const Shape& shape, const Vec3& inside_point, const Vec3& outside_point,
                              double tolerance = 1e-12);

}  // namespace hs::common
