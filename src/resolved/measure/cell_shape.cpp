// SPDX-License-Identifier: MIT
// The shape measures of a deformed cell from its membrane vertices.
#include "resolved/measure/cell_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace hs::resolved {

using common::Vec3;

CellShape measure_cell_shape(std::span<const Vec3> vertices_m) {
  if (vertices_m.size() < 4) throw std::invalid_argument("measure_cell_shape: need at least 4 vertices");
  CellShape s;
  for (const auto& v : vertices_m) s.centroid_m += v;
  s.centroid_m = s.centroid_m / static_cast<double>(vertices_m.size());
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (const auto& v : vertices_m) {
    const Eigen::Vector3d r(v.x - s.centroid_m.x, v.y - s.centroid_m.y, v.z - s.centroid_m.z);
    g += r * r.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(g);   // eigenvalues ascending
  for (int k = 0; k < 3; ++k) {
    s.gyration_radii_m[static_cast<std::size_t>(k)] =
        std::sqrt(std::max(0.0, eig.eigenvalues()(2 - k)) / static_cast<double>(vertices_m.size()));
  }
  std::array<Vec3, 3> axes;
  std::array<double, 3> extents{};
  for (int k = 0; k < 3; ++k) {
    const auto col = eig.eigenvectors().col(2 - k);
    axes[static_cast<std::size_t>(k)] = {col(0), col(1), col(2)};
  }
  for (std::size_t k = 0; k < 3; ++k) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const auto& v : vertices_m) {
      const double p = dot(v - s.centroid_m, axes[k]);
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
    extents[k] = hi - lo;
  }
  // Order by measured extent (the second moment orders by spread, which can differ for odd shapes).
  std::array<std::size_t, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return extents[a] > extents[b]; });
  for (std::size_t k = 0; k < 3; ++k) {
    s.axes[k] = axes[order[k]];
    s.extents_m[k] = extents[order[k]];
  }
  for (int i = 0; i < 3; ++i) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const auto& v : vertices_m) {
      lo = std::min(lo, v[i]);
      hi = std::max(hi, v[i]);
    }
    s.projected_m[static_cast<std::size_t>(i)] = hi - lo;
  }
  return s;
}

double inclination_angle(const CellShape& shape, const Vec3& flow, const Vec3& gradient) {
  const Vec3& a = shape.axes[0];
  double angle = std::atan2(dot(a, normalized(gradient)), dot(a, normalized(flow)));
  // An axis has no sign: fold into (-pi/2, pi/2].
  if (angle > std::numbers::pi / 2) angle -= std::numbers::pi;
  if (angle <= -std::numbers::pi / 2) angle += std::numbers::pi;
  return angle;
}

double normal_to_vorticity_angle(const CellShape& shape, const Vec3& vorticity) {
  const double c = std::abs(dot(shape.axes[2], normalized(vorticity)));   // an axis has no sign
  return std::acos(std::min(1.0, c));
}

}  // namespace hs::resolved
