// SPDX-License-Identifier: MIT
// Evans–Fung biconcave shape: profile, implicit function and Newton projection.
#include "resolved/membrane/evans_fung_shape.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::resolved {

using hs::common::Vec3;

EvansFungShape::EvansFungShape(double diameter_m) : d0_m_(diameter_m) {
  if (!(diameter_m > 0.0)) {
    throw hs::common::ConfigError(fmt::format("RBC diameter_m = {} must be > 0 (human RBC: 7.82e-6 m)", diameter_m));
  }
}

double EvansFungShape::half_thickness_m(double r_m) const {
  const double s = (r_m / d0_m_) * (r_m / d0_m_);
  if (4.0 * s >= 1.0) return 0.0;
  return d0_m_ * std::sqrt(1.0 - 4.0 * s) * (a0_ + a1_ * s + a2_ * s * s);
}

double EvansFungShape::implicit(const Vec3& p_m) const {
  const Vec3 q = p_m / d0_m_;
  const double s = q.x * q.x + q.y * q.y;
  const double poly = a0_ + a1_ * s + a2_ * s * s;
  return q.z * q.z - (1.0 - 4.0 * s) * poly * poly;
}

Vec3 EvansFungShape::implicit_gradient(const Vec3& p_m) const {
  const Vec3 q = p_m / d0_m_;
  const double s = q.x * q.x + q.y * q.y;
  const double poly = a0_ + a1_ * s + a2_ * s * s;
  const double dpoly = a1_ + 2.0 * a2_ * s;
  const double dphi_ds = 4.0 * poly * poly - (1.0 - 4.0 * s) * 2.0 * poly * dpoly;
  return Vec3{2.0 * q.x * dphi_ds, 2.0 * q.y * dphi_ds, 2.0 * q.z} / d0_m_;   // d/dp of Phi(p/D0)
}

Vec3 EvansFungShape::project(const Vec3& p_m) const {
  Vec3 p = p_m;
  constexpr int max_newton_steps = 50;
  for (int it = 0; it < max_newton_steps; ++it) {
    const double phi = implicit(p);
    if (std::abs(phi) < 1e-14) break;   // |Phi| ~ relative distance squared: 1e-14 is round-off level
    const Vec3 g = implicit_gradient(p);
    p -= g * (phi / dot(g, g));
  }
  return p;
}

}  // namespace hs::resolved
