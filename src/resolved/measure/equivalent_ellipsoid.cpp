// SPDX-License-Identifier: MIT
// Volume, centroid and second moment of a closed triangle surface, and the ellipsoid that shares them.
#include "resolved/measure/equivalent_ellipsoid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace hs::resolved {

using common::Vec3;

EquivalentEllipsoid equivalent_ellipsoid(std::span<const Vec3> vertices_m, std::span<const std::array<int, 3>> triangles) {
  if (vertices_m.size() < 4 || triangles.size() < 4) throw std::invalid_argument("equivalent_ellipsoid: not a closed surface");
  // Moments about the vertex mean o (any point works; one inside keeps the sums well conditioned).
  Vec3 o;
  for (const auto& v : vertices_m) o += v;
  o = o / static_cast<double>(vertices_m.size());
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& t : triangles) {
    const auto rel = [&](int i) {
      const Vec3 d = vertices_m[static_cast<std::size_t>(i)] - o;
      return Eigen::Vector3d(d.x, d.y, d.z);
    };
    const Eigen::Vector3d a = rel(t[0]), b = rel(t[1]), c = rel(t[2]);
    // Tetrahedron (o, a, b, c), signed volume v: integral of x = v (a + b + c) / 4, of x x^T = v/20 (a a^T + b b^T +
    // c c^T + s s^T) with s = a + b + c (the unit tetrahedron's moments (1 + delta_ij) / 120 mapped by [a b c]).
    const double v = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    volume += v;
    first += v * s / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  if (!(volume > 0.0)) throw std::invalid_argument("equivalent_ellipsoid: the surface encloses no positive volume");
  const Eigen::Vector3d d = first / volume;   // centroid relative to o
  const Eigen::Matrix3d central = second - volume * d * d.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(central);   // ascending
  EquivalentEllipsoid e;
  e.volume_m3 = volume;
  e.centroid_m = o + Vec3{d(0), d(1), d(2)};
  for (int k = 0; k < 3; ++k) {
    const auto col = eig.eigenvectors().col(2 - k);
    e.axes[static_cast<std::size_t>(k)] = {col(0), col(1), col(2)};
    // A solid ellipsoid's second moment along axis i is V a_i^2 / 5.
    e.semi_axes_m[static_cast<std::size_t>(k)] = std::sqrt(std::max(0.0, 5.0 * eig.eigenvalues()(2 - k) / volume));
  }
  return e;
}

double EquivalentEllipsoid::shear_plane_taylor_deformation(const Vec3& vorticity) const {
  std::size_t out = 0;
  for (std::size_t k = 1; k < 3; ++k) {
    if (std::abs(dot(axes[k], vorticity)) > std::abs(dot(axes[out], vorticity))) out = k;
  }
  const double a1 = semi_axes_m[out == 0 ? 1 : 0];   // the larger of the two kept (descending order)
  const double a2 = semi_axes_m[out == 2 ? 1 : 2];
  return (a1 - a2) / (a1 + a2);
}

}  // namespace hs::resolved
