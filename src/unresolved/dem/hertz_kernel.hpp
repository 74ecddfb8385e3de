// SPDX-License-Identifier: MIT
// The Hertz + history contact force of one contact (particle-particle or particle-wall), as a small kernel.
#pragma once

#include <array>
#include <cmath>

#include "unresolved/dem/hertz_contact_law.hpp"

namespace hs::unresolved {

/// Geometry and kinematics of one contact, from particle i's side. n points from the partner to i.
struct ContactInput {
  double n[3];          // unit normal, partner -> i
  double delta_m;       // overlap > 0
  double v_rel[3];      // velocity of i's contact point minus the partner's (m/s)
  double r_eff_m;       // R*
  double m_eff_kg;      // m*
};

/// Force on i (the partner gets minus it), after LIGGGHTS hertz + tangential history (unresolved-methods 4.2, 4.4):
///   F_n = (4/3) Y* sqrt(R* delta) delta - gamma_n v_n, gamma_n = -2 sqrt(5/6) beta sqrt(2 Y* sqrt(R* delta) m*);
///   s <- s rotated into the tangent plane (magnitude kept) + v_t dt;  F_t = -k_t s - gamma_t v_t, k_t = 8 G* sqrt(R* delta);
///   Coulomb: if k_t |s| > mu |F_n| then s <- s mu |F_n| / (k_t |s|), F_t = -k_t s (no damping while sliding).
/// pre: delta_m > 0, |n| = 1. post: shear_m updated in place; returns F on i; f_t_out the tangential part.
inline std::array<double, 3> hertz_contact_force(const ContactInput& c, const PairConstants& k, bool limit_normal,
                                                 double dt_s, double* shear_m, double* f_t_out) {
  const double vn = c.v_rel[0] * c.n[0] + c.v_rel[1] * c.n[1] + c.v_rel[2] * c.n[2];   // < 0 approaching
  const double vt[3] = {c.v_rel[0] - vn * c.n[0], c.v_rel[1] - vn * c.n[1], c.v_rel[2] - vn * c.n[2]};
  const double a = std::sqrt(c.r_eff_m * c.delta_m);            // contact radius
  const double sqrt_ma = std::sqrt(c.m_eff_kg * a);
  double fn = (4.0 / 3.0) * k.y_eff_Pa * a * c.delta_m - k.damping_n * sqrt_ma * vn;
  if (limit_normal && fn < 0.0) fn = 0.0;

  const double s2_old = shear_m[0] * shear_m[0] + shear_m[1] * shear_m[1] + shear_m[2] * shear_m[2];
  if (s2_old > 0.0) {
    const double sn = shear_m[0] * c.n[0] + shear_m[1] * c.n[1] + shear_m[2] * c.n[2];
    for (int d = 0; d < 3; ++d) shear_m[d] -= sn * c.n[d];
    // Keep |s|: scale = 1 / sqrt(1 - q), q = (s.n)^2 / |s|^2 (tiny: the normal turns by ~v dt / r per step);
    // the series 1 + q/2 + 3q^2/8 is exact to 5/16 q^3 < 4e-10 for q < 1e-3 and saves a sqrt and a division.
    const double q = sn * sn / s2_old;
    const double scale = q < 1e-3 ? 1.0 + q * (0.5 + 0.375 * q) : (q < 1.0 ? 1.0 / std::sqrt(1.0 - q) : 0.0);
    for (int d = 0; d < 3; ++d) shear_m[d] *= scale;
  }
  for (int d = 0; d < 3; ++d) shear_m[d] += vt[d] * dt_s;
  const double kt = 8.0 * k.g_eff_Pa * a;
  const double gt = k.damping_t * sqrt_ma;
  const double s2 = shear_m[0] * shear_m[0] + shear_m[1] * shear_m[1] + shear_m[2] * shear_m[2];
  const double f_friction = k.friction * std::fabs(fn);
  double ft[3];
  if (kt * kt * s2 > f_friction * f_friction) {
    const double ratio = f_friction / (kt * std::sqrt(s2));
    for (int d = 0; d < 3; ++d) {
      shear_m[d] *= ratio;
      ft[d] = -kt * shear_m[d];
    }
  } else {
    for (int d = 0; d < 3; ++d) ft[d] = -kt * shear_m[d] - gt * vt[d];
  }
  for (int d = 0; d < 3; ++d) f_t_out[d] = ft[d];
  return {fn * c.n[0] + ft[0], fn * c.n[1] + ft[1], fn * c.n[2] + ft[2]};
}

}  // namespace hs::unresolved
