// SPDX-License-Identifier: MIT
// The fused pull-stream + TRT/BGK collision kernel with Guo forcing.
#include "resolved/lbm/stream_collide.hpp"

namespace hs::resolved {
namespace {

using C = D3Q19;
constexpr std::ptrdiff_t kMinRunsForThreads = 256;

/// Updates nodes [begin, end). The loop body is straight-line code over the 19 directions, so the
/// compiler unrolls it and vectorises along x.
template <bool kForceField>
void update_run(const StreamCollideArgs& a, const std::array<const double*, C::q>& pull,
                const std::array<double*, C::q>& out, std::ptrdiff_t begin, std::ptrdiff_t end) {
  const double wp = a.omega_plus;
  const double wm = a.omega_minus;
  const double sp = 1.0 - 0.5 * wp;
  const double sm = 1.0 - 0.5 * wm;
  const std::ptrdiff_t vol = static_cast<std::ptrdiff_t>(a.volume);
#pragma omp simd
  for (std::ptrdiff_t n = begin; n < end; ++n) {
    double f[C::q];
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) f[i] = pull[static_cast<std::size_t>(i)][n];
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
    double fx = a.body_force.x;
    double fy = a.body_force.y;
    double fz = a.body_force.z;
    if constexpr (kForceField) {
      fx += a.force_field[n];
      fy += a.force_field[vol + n];
      fz += a.force_field[2 * vol + n];
    }
    const double inv_rho = 1.0 / rho;
    const double ux = (jx + 0.5 * fx) * inv_rho;
    const double uy = (jy + 0.5 * fy) * inv_rho;
    const double uz = (jz + 0.5 * fz) * inv_rho;
    const double usq = ux * ux + uy * uy + uz * uz;
    const double uf = ux * fx + uy * fy + uz * fz;
    const double feq0 = C::w0 * rho * (1.0 - 1.5 * usq);
    out[0][n] = f[0] - wp * (f[0] - feq0) + sp * C::w0 * (-3.0 * uf);
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
      const double post_even = f_even - wp * (f_even - feq_even) + sp * w * (9.0 * cu * cf - 3.0 * uf);
      const double post_odd = f_odd - wm * (f_odd - feq_odd) + sm * w * 3.0 * cf;
      out[static_cast<std::size_t>(k)][n] = post_even + post_odd;
      out[static_cast<std::size_t>(k + C::half)][n] = post_even - post_odd;
    }
  }
}

}  // namespace

void stream_collide(const StreamCollideArgs& a) {
  std::array<const double*, C::q> pull{};
  std::array<double*, C::q> out{};
  for (std::size_t i = 0; i < C::q; ++i) {
    pull[i] = a.src + i * a.volume - a.offset[i];
    out[i] = a.dst + i * a.volume;
  }
  const auto runs = static_cast<std::ptrdiff_t>(a.runs.size());
  const bool has_field = a.force_field != nullptr;
  // Tiny blocks (tests, thin slabs) run on one thread: a parallel region costs more than they do.
#pragma omp parallel for schedule(static) if (runs >= kMinRunsForThreads)
  for (std::ptrdiff_t r = 0; r < runs; ++r) {
    const FluidRun run = a.runs[static_cast<std::size_t>(r)];
    if (has_field) {
      update_run<true>(a, pull, out, run.begin, run.begin + run.length);
    } else {
      update_run<false>(a, pull, out, run.begin, run.begin + run.length);
    }
  }
}

}  // namespace hs::resolved
