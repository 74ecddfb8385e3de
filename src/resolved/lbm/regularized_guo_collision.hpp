// SPDX-License-Identifier: MIT
// The node-local regularised collision with Guo forcing (bulk operator of CollisionModel::regularized).
#pragma once

#include "resolved/lbm/d3q19.hpp"
#include "resolved/lbm/trt_guo_collision.hpp"

namespace hs::resolved {

/// The even part regularised (Latt & Chopard 2006, Math. Comput. Simul. 72:165; Krueger et al. 2017, section
/// 10.6.4): before relaxing, the even non-equilibrium part is replaced by its projection on the second-order Hermite
/// polynomials,
///   f1_i = w_i / (2 c_s^4) Q_i : Pi1,   Q_i = c_i c_i - c_s^2 I,   Pi1 = sum_i f_i c_i c_i - rho u u - rho c_s^2 I,
///   f+*_i = f+eq_i + (1 - w+) f1_i + (1 - w+/2) S+_i,
/// so the even moments outside {rho, Pi} (the fourth-order "ghosts") are reset to equilibrium each step, where TRT
/// relaxes them at w+ = 1/tau (1.6 % per step at tau 60). The odd part is TRT's (trt_guo_collide) with the rate r.wm,
/// which CollisionParams bounds below 2 (the odd ghosts at Lambda = 3/16 lose 1 % per step at tau 60). The
/// hydrodynamic moments after the collision are those of TRT (same viscosity, same force).
/// Evaluated per pair (k, -k) as trt_guo_collide.
[[gnu::always_inline]] inline void regularized_guo_collide(const double (&f)[D3Q19::q], double fx, double fy,
                                                           double fz, const TrtRates& r, double (&post)[D3Q19::q]) {
  using C = D3Q19;
  double sum[C::half + 1];
  double diff[C::half + 1];
  double rho = f[0];
#pragma GCC unroll 9
  for (int k = 1; k <= C::half; ++k) {
    sum[k] = f[k] + f[k + C::half];
    diff[k] = f[k] - f[k + C::half];
    rho += sum[k];
  }
  const double jx = diff[1] + diff[4] + diff[5] + diff[6] + diff[7];
  const double jy = diff[2] + diff[4] - diff[5] + diff[8] + diff[9];
  const double jz = diff[3] + diff[6] - diff[7] + diff[8] - diff[9];
  const double mx = jx + 0.5 * fx;   // rho u
  const double my = jy + 0.5 * fy;
  const double mz = jz + 0.5 * fz;
  const double inv_rho = 1.0 / rho;
  const double ux = mx * inv_rho;
  const double uy = my * inv_rho;
  const double uz = mz * inv_rho;
  // Pi1 = Pi - rho u u - rho c_s^2 I from the pair sums (sum_k c_k c_k (f_k + f_-k)).
  const double p_iso = rho * C::cs2;
  const double pxx = sum[1] + sum[4] + sum[5] + sum[6] + sum[7] - mx * ux - p_iso;
  const double pyy = sum[2] + sum[4] + sum[5] + sum[8] + sum[9] - my * uy - p_iso;
  const double pzz = sum[3] + sum[6] + sum[7] + sum[8] + sum[9] - mz * uz - p_iso;
  const double pxy = sum[4] - sum[5] - mx * uy;
  const double pxz = sum[6] - sum[7] - mx * uz;
  const double pyz = sum[8] - sum[9] - my * uz;
  // 4.5 (1 - w+) (Q_k : Pi1) = a (c_k c_k : Pi1) - b, with b the isotropic part.
  const double a = 4.5 * (1.0 - r.wp);
  const double iso = a * C::cs2 * (pxx + pyy + pzz);
  const double qf[C::half + 1] = {0.0,
                                  a * pxx - iso,
                                  a * pyy - iso,
                                  a * pzz - iso,
                                  a * (pxx + pyy + 2.0 * pxy) - iso,
                                  a * (pxx + pyy - 2.0 * pxy) - iso,
                                  a * (pxx + pzz + 2.0 * pxz) - iso,
                                  a * (pxx + pzz - 2.0 * pxz) - iso,
                                  a * (pyy + pzz + 2.0 * pyz) - iso,
                                  a * (pyy + pzz - 2.0 * pyz) - iso};
  const double usq = ux * ux + uy * uy + uz * uz;
  const double uf = ux * fx + uy * fy + uz * fz;
  const double base = rho * (1.0 - 1.5 * usq) - 3.0 * r.sp * uf;
  const double g = 4.5 * rho;
  const double hx = 9.0 * r.sp * fx;
  const double hy = 9.0 * r.sp * fy;
  const double hz = 9.0 * r.sp * fz;
  const double vx = 3.0 * (r.wm * mx + r.sm * fx);
  const double vy = 3.0 * (r.wm * my + r.sm * fy);
  const double vz = 3.0 * (r.wm * mz + r.sm * fz);
  post[0] = C::w0 * (base - iso);
#pragma GCC unroll 9
  for (int k = 1; k <= C::half; ++k) {
    const double w = C::w[static_cast<std::size_t>(k)];
    const double cu = c_dot(k, ux, uy, uz);
    const double even = w * (base + qf[k] + cu * (g * cu + c_dot(k, hx, hy, hz)));
    const double odd = r.keep_odd * diff[k] + w * c_dot(k, vx, vy, vz);
    post[k] = even + odd;
    post[k + C::half] = even - odd;
  }
}

}  // namespace hs::resolved
