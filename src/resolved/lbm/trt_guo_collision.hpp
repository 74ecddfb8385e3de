// SPDX-License-Identifier: MIT
// The node-local TRT/BGK collision with Guo forcing, shared by the two-buffer and the AA-pattern kernels.
#pragma once

#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

/// Relaxation rates of one collision: w+ = 1/tau+, w- = 1/tau-, and the Guo source prefactors 1 - w/2.
struct TrtRates {
  double wp;
  double wm;
  double sp;
  double sm;
};

inline TrtRates trt_rates(double omega_plus, double omega_minus) {
  return {.wp = omega_plus, .wm = omega_minus, .sp = 1.0 - 0.5 * omega_plus, .sm = 1.0 - 0.5 * omega_minus};
}

/// Pre-collision populations f of one node and its force density (fx, fy, fz) to post-collision ones:
///   moments: rho = sum f_i,  u = (sum f_i c_i + F/2) / rho           (Guo, Zheng & Shi 2002)
///   TRT:     f*_i = f_i - w+ (f+_i - f+eq_i) - w- (f-_i - f-eq_i) + (1 - w+/2) S+_i + (1 - w-/2) S-_i
/// with S+_i = w_i [9 (c.u)(c.F) - 3 u.F], S-_i = 3 w_i c.F (Ginzburg et al. 2008; Krueger et al. 2017, 6.3 and 10.7).
/// Straight-line code over the 19 directions, always inlined, so the callers' node loops vectorise along x.
[[gnu::always_inline]] inline void trt_guo_collide(const double (&f)[D3Q19::q], double fx, double fy, double fz,
                                                   const TrtRates& r, double (&post)[D3Q19::q]) {
  using C = D3Q19;
  double rho = 0.0;
  double jx = 0.0;
  double jy = 0.0;
  double jz = 0.0;
#pragma GCC unroll 19
  for (int i = 0; i < C::q; ++i) {
    rho += f[i];
    jx += C::c[static_cast<std::size_t>(i)][0] * f[i];
    jy += C::c[static_cast<std::size_t>(i)][1] * f[i];
    jz += C::c[static_cast<std::size_t>(i)][2] * f[i];
  }
  const double inv_rho = 1.0 / rho;
  const double ux = (jx + 0.5 * fx) * inv_rho;
  const double uy = (jy + 0.5 * fy) * inv_rho;
  const double uz = (jz + 0.5 * fz) * inv_rho;
  const double usq = ux * ux + uy * uy + uz * uz;
  const double uf = ux * fx + uy * fy + uz * fz;
  const double feq0 = C::w0 * rho * (1.0 - 1.5 * usq);
  post[0] = f[0] - r.wp * (f[0] - feq0) + r.sp * C::w0 * (-3.0 * uf);
#pragma GCC unroll 9
  for (int k = 1; k <= C::half; ++k) {
    const auto& c = C::c[static_cast<std::size_t>(k)];
    const double w = C::w[static_cast<std::size_t>(k)];
    const double cu = c[0] * ux + c[1] * uy + c[2] * uz;
    const double cf = c[0] * fx + c[1] * fy + c[2] * fz;
    const double feq_even = w * rho * (1.0 + 4.5 * cu * cu - 1.5 * usq);
    const double feq_odd = w * rho * 3.0 * cu;
    const double f_even = 0.5 * (f[k] + f[k + C::half]);
    const double f_odd = 0.5 * (f[k] - f[k + C::half]);
    const double post_even = f_even - r.wp * (f_even - feq_even) + r.sp * w * (9.0 * cu * cf - 3.0 * uf);
    const double post_odd = f_odd - r.wm * (f_odd - feq_odd) + r.sm * w * 3.0 * cf;
    post[k] = post_even + post_odd;
    post[k + C::half] = post_even - post_odd;
  }
}

}  // namespace hs::resolved
