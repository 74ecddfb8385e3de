// SPDX-License-Identifier: MIT
// Building shapes from shapes: union, intersection, difference, and rigid transforms.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "common/geometry/shape.hpp"

namespace hs::common {

/// Fluid in any of the parts (minimum of signed distances; exact outside, a bound inside).
class ShapeUnion final : public Shape {
 public:
  explicit ShapeUnion(std::vector<std::shared_ptr<const Shape>> parts);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;

 private:
  std::vector<std::shared_ptr<const Shape>> parts_;
};

/// Fluid in all of the parts (maximum of signed distances), e.g. a tube clipped to a box.
class ShapeIntersection final : public Shape {
 public:
  explicit ShapeIntersection(std::vector<std::shared_ptr<const Shape>> parts);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;

 private:
  std::vector<std::shared_ptr<const Shape>> parts_;
};

/// Fluid in `base` but not in `removed` (an obstacle inside a channel).
class ShapeDifference final : public Shape {
 public:
  ShapeDifference(std::shared_ptr<const Shape> base, std::shared_ptr<const Shape> removed);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override { return base_->bounds(); }

 private:
  std::shared_ptr<const Shape> base_;
  std::shared_ptr<const Shape> removed_;
};

/// A shape moved rigidly: p_world = R p_local + t. Distances are preserved.
class TransformedShape final : public Shape {
 public:
  using Matrix3 = std::array<std::array<double, 3>, 3>;
  TransformedShape(std::shared_ptr<const Shape> shape, const Matrix3& rotation, const Vec3& translation_m);
  /// Rotation by `angle_rad` about the unit `axis` (Rodrigues), then translation.
  static TransformedShape rotate_translate(std::shared_ptr<const Shape> shape, const Vec3& axis, double angle_rad,
                                           const Vec3& translation_m);
  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override;

 private:
  std::shared_ptr<const Shape> shape_;
  Matrix3 rotation_;
  Vec3 translation_m_;
};

}  // namespace hs::common
