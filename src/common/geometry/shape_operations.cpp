// SPDX-License-Identifier: MIT
// Building shapes from shapes.
#include "common/geometry/shape_operations.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hs::common {
namespace {

Box3 merge(const Box3& a, const Box3& b, bool grow) {
  Box3 out;
  for (int i = 0; i < 3; ++i) {
    out.lo[i] = grow ? std::min(a.lo[i], b.lo[i]) : std::max(a.lo[i], b.lo[i]);
    out.hi[i] = grow ? std::max(a.hi[i], b.hi[i]) : std::min(a.hi[i], b.hi[i]);
  }
  return out;
}

void require_parts(const std::vector<std::shared_ptr<const Shape>>& parts) {
  if (parts.empty()) throw std::invalid_argument("shape operation needs at least one part");
  for (const auto& p : parts) {
    if (!p) throw std::invalid_argument("shape operation got a null part");
  }
}

}  // namespace

ShapeUnion::ShapeUnion(std::vector<std::shared_ptr<const Shape>> parts) : parts_(std::move(parts)) { require_parts(parts_); }

double ShapeUnion::signed_distance(const Vec3& p_m) const {
  double d = HUGE_VAL;
  for (const auto& s : parts_) d = std::min(d, s->signed_distance(p_m));
  return d;
}

Box3 ShapeUnion::bounds() const {
  Box3 b = parts_.front()->bounds();
  for (const auto& s : parts_) b = merge(b, s->bounds(), true);
  return b;
}

ShapeIntersection::ShapeIntersection(std::vector<std::shared_ptr<const Shape>> parts) : parts_(std::move(parts)) {
  require_parts(parts_);
}

double ShapeIntersection::signed_distance(const Vec3& p_m) const {
  double d = -HUGE_VAL;
  for (const auto& s : parts_) d = std::max(d, s->signed_distance(p_m));
  return d;
}

Box3 ShapeIntersection::bounds() const {
  Box3 b = parts_.front()->bounds();
  for (const auto& s : parts_) b = merge(b, s->bounds(), false);
  return b;
}

ShapeDifference::ShapeDifference(std::shared_ptr<const Shape> base, std::shared_ptr<const Shape> removed)
    : base_(std::move(base)), removed_(std::move(removed)) {
  if (!base_ || !removed_) throw std::invalid_argument("ShapeDifference: null shape");
}

double ShapeDifference::signed_distance(const Vec3& p_m) const {
  return std::max(base_->signed_distance(p_m), -removed_->signed_distance(p_m));
}

TransformedShape::TransformedShape(std::shared_ptr<const Shape> shape, const Matrix3& rotation, const Vec3& translation_m)
    : shape_(std::move(shape)), rotation_(rotation), translation_m_(translation_m) {
  if (!shape_) throw std::invalid_argument("TransformedShape: null shape");
}

TransformedShape TransformedShape::rotate_translate(std::shared_ptr<const Shape> shape, const Vec3& axis, double angle_rad,
                                                    const Vec3& translation_m) {
  const Vec3 k = normalized(axis);
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  const double v = 1.0 - c;
  const Matrix3 r{{{c + k.x * k.x * v, k.x * k.y * v - k.z * s, k.x * k.z * v + k.y * s},
                   {k.y * k.x * v + k.z * s, c + k.y * k.y * v, k.y * k.z * v - k.x * s},
                   {k.z * k.x * v - k.y * s, k.z * k.y * v + k.x * s, c + k.z * k.z * v}}};
  return TransformedShape(std::move(shape), r, translation_m);
}

double TransformedShape::signed_distance(const Vec3& p_m) const {
  const Vec3 q = p_m - translation_m_;
  Vec3 local;   // R^T q
  for (int i = 0; i < 3; ++i) local[i] = rotation_[0][i] * q.x + rotation_[1][i] * q.y + rotation_[2][i] * q.z;
  return shape_->signed_distance(local);
}

Box3 TransformedShape::bounds() const {
  // Transform the 8 corners of the local box and take their extent.
  const Box3 b = shape_->bounds();
  Box3 out{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{(c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z};
    for (int i = 0; i < 3; ++i) {
      const double w = rotation_[i][0] * p.x + rotation_[i][1] * p.y + rotation_[i][2] * p.z + translation_m_[i];
      out.lo[i] = std::min(out.lo[i], w);
      out.hi[i] = std::max(out.hi[i], w);
    }
  }
  return out;
}

}  // namespace hs::common
