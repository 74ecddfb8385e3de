// SPDX-License-Identifier: MIT
// A parent tube splitting into two daughter tubes.
#include "common/geometry/bifurcation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hs::common {
namespace {

/// Signed distance to a tube that starts at `origin` (closed by a flat cap there) and runs forever along `dir`.
double ray_tube_distance(const Vec3& p, const Vec3& origin, const Vec3& dir, double radius) {
  const Vec3 r = p - origin;
  const double t = dot(r, dir);
  const double rho = norm(r - t * dir);
  if (t >= 0.0) return std::max(rho - radius, -t);   // inside: the nearer of wall and cap
  const double radial = std::max(rho - radius, 0.0);
  return std::sqrt(radial * radial + t * t);
}

}  // namespace

Bifurcation::Bifurcation(const BifurcationSpec& spec) : spec_(spec) {
  directions_[0] = {-1.0, 0.0, 0.0};
  radii_[0] = spec.parent_radius_m;
  lengths_[0] = spec.parent_length_m;
  for (std::size_t i = 0; i < 2; ++i) {
    const double a = spec.daughter_angle_deg[i] * std::numbers::pi / 180.0;
    directions_[i + 1] = {std::cos(a), std::sin(a), 0.0};
    radii_[i + 1] = spec.daughter_radius_m[i];
    lengths_[i + 1] = spec.daughter_length_m[i];
    if (std::abs(spec.daughter_angle_deg[i]) >= 180.0) throw std::invalid_argument("Bifurcation: |angle| must be < 180 deg");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(radii_[i] > 0.0) || !(lengths_[i] > radii_[i])) {
      throw std::invalid_argument("Bifurcation: radii must be > 0 and each branch longer than its radius");
    }
  }
}

double Bifurcation::signed_distance(const Vec3& p_m) const {
  double d = norm(p_m - spec_.junction_m) - radii_[0];
  for (std::size_t i = 0; i < 3; ++i) d = std::min(d, ray_tube_distance(p_m, spec_.junction_m, directions_[i], radii_[i]));
  return d;
}

Box3 Bifurcation::bounds() const {
  Box3 b{spec_.junction_m - Vec3{radii_[0], radii_[0], radii_[0]}, spec_.junction_m + Vec3{radii_[0], radii_[0], radii_[0]}};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3 end = spec_.junction_m + lengths_[i] * directions_[i];
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], end[k] - radii_[i]);
      b.hi[k] = std::max(b.hi[k], end[k] + radii_[i]);
    }
  }
  return b;
}

}  // namespace hs::common
