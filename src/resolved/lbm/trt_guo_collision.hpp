// SPDX-License-Identifier: MIT
// The node-local TRT/BGK collision with Guo forcing, shared by the two-buffer and the AA-pattern kernels.
#pragma once

#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

/// Relaxation rates of one collision and the factors the collision derives from them (per run, not per node):
/// w+ = 1/tau+, w- = 1/tau-, and the Guo source prefactors 1 - w/2.
struct TrtRates {
  double wp;
  double wm;
  double sp;
  double sm;
  double keep_even;   // (1 - w+)/2: share of (f_k + f_-k) kept
  double keep_odd;    // (1 - w-)/2: share of (f_k - f_-k) kept
};

inline TrtRates trt_rates(double omega_plus, double omega_minus) {
  const double sp = 1.0 - 0.5 * omega_plus;
  const double sm = 1.0 - 0.5 * omega_minus;
  return {.wp = omega_plus, .wm = omega_minus, .sp = sp, .sm = sm, .keep_even = 0.5 * (1.0 - omega_plus),
          .keep_odd = 0.5 * (1.0 - omega_minus)};
}

/// c_k . (x, y, z) for the components of c_k (0 or +-1). Called with k known after unrolling, so the branches fold
/// away: IEEE arithmetic forbids the compiler to drop 0 * x itself (x may be inf or NaN), and those products were a
/// third of the collision's work.
[[gnu::always_inline]] inline double c_dot(int k, double x, double y, double z) {
  const auto& c = D3Q19::c[static_cast<std::size_t>(k)];
  const double tx = c[0] > 0 ? x : -x;
  const double ty = c[1] > 0 ? y : -y;
  const double tz = c[2] > 0 ? z : -z;
  if (c[0] == 0) return c[1] == 0 ? tz : (c[2] == 0 ? ty : ty + tz);
  if (c[1] == 0) return c[2] == 0 ? tx : tx + tz;
  return tx + ty;
}

/// Pre-collision populations f of one node and its force density (fx, fy, fz) to post-collision ones:
///   moments: rho = sum f_i,  u = (sum f_i c_i + F/2) / rho           (Guo, Zheng & Shi 2002)
///   TRT:     f*_i = f_i - w+ (f+_i - f+eq_i) - w- (f-_i - f-eq_i) + (1 - w+/2) S+_i + (1 - w-/2) S-_i
/// with S+_i = w_i [9 (c.u)(c.F) - 3 u.F], S-_i = 3 w_i c.F (Ginzburg et al. 2008; Krueger et al. 2017, 6.3 and 10.7).
/// Evaluated per pair (k, -k) as (the same expression, regrouped):
///   f+*_k = (1 - w+)/2 (f_k + f_-k) + w_k [B + c.u (4.5 w+ rho c.u + 9 (1 - w+/2) c.F)]
///           with B = w+ rho (1 - 1.5 u.u) - 3 (1 - w+/2) u.F
///   f-*_k = (1 - w-)/2 (f_k - f_-k) + w_k c.V,  V = 3 w- rho u + 3 (1 - w-/2) F,  rho u = j + F/2 (no division)
///   f*_k = f+*_k + f-*_k,  f*_-k = f+*_k - f-*_k
/// Straight-line code over the 19 directions, always inlined, so the callers' node loops vectorise along x.
[[gnu::always_inline]] inline void trt_guo_collide(const double (&f)[D3Q19::q], double fx, double fy, double fz,
                                                   const TrtRates& r, double (&post)[D3Q19::q]) {
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
  // j = sum_k c_k (f_k - f_-k) over the pairs k = 1..9 (d3q19.hpp).
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
  const double usq = ux * ux + uy * uy + uz * uz;
  const double uf = ux * fx + uy * fy + uz * fz;
  const double base = r.wp * rho * (1.0 - 1.5 * usq) - 3.0 * r.sp * uf;
  const double g = 4.5 * r.wp * rho;
  const double hx = 9.0 * r.sp * fx;
  const double hy = 9.0 * r.sp * fy;
  const double hz = 9.0 * r.sp * fz;
  const double vx = 3.0 * (r.wm * mx + r.sm * fx);
  const double vy = 3.0 * (r.wm * my + r.sm * fy);
  const double vz = 3.0 * (r.wm * mz + r.sm * fz);
  post[0] = (1.0 - r.wp) * f[0] + C::w0 * base;
#pragma GCC unroll 9
  for (int k = 1; k <= C::half; ++k) {
    const double w = C::w[static_cast<std::size_t>(k)];
    const double cu = c_dot(k, ux, uy, uz);
    const double even = r.keep_even * sum[k] + w * (base + cu * (g * cu + c_dot(k, hx, hy, hz)));
    const double odd = r.keep_odd * diff[k] + w * c_dot(k, vx, vy, vz);
    post[k] = even + odd;
    post[k + C::half] = even - odd;
  }
}

}  // namespace hs::resolved
