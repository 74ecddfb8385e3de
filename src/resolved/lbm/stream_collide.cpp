// SPDX-License-Identifier: MIT
// The fused pull-stream + TRT/BGK collision kernel with Guo forcing.
#include "resolved/lbm/stream_collide.hpp"

#include <immintrin.h>

#include <algorithm>

#include "resolved/lbm/regularized_guo_collision.hpp"
#include "resolved/lbm/trt_guo_collision.hpp"

namespace hs::resolved {
namespace {

using C = D3Q19;

/// Updates nodes [begin, end), writing direction k of node n to out[k][n - out_shift]. The collision is inlined
/// straight-line code over the 19 directions, so the loop vectorises along x.
template <bool kForceField, bool kRegularized>
void update_nodes(const StreamCollideArgs& a, const TrtRates& rates, const std::array<const double*, C::q>& pull,
                  const std::array<double*, C::q>& out, std::ptrdiff_t out_shift, std::ptrdiff_t begin,
                  std::ptrdiff_t end) {
  const std::ptrdiff_t vol = static_cast<std::ptrdiff_t>(a.force_stride);
#pragma omp simd
  for (std::ptrdiff_t n = begin; n < end; ++n) {
    double f[C::q];
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) f[i] = pull[static_cast<std::size_t>(i)][n];
    double fx = a.body_force.x;
    double fy = a.body_force.y;
    double fz = a.body_force.z;
    if constexpr (kForceField) {
      fx += a.force_field[n];
      fy += a.force_field[vol + n];
      fz += a.force_field[2 * vol + n];
    }
    double post[C::q];
    if constexpr (kRegularized) {
      regularized_guo_collide(f, fx, fy, fz, rates, post);
    } else {
      trt_guo_collide(f, fx, fy, fz, rates, post);
    }
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) out[static_cast<std::size_t>(i)][n - out_shift] = post[i];
  }
}

/// Updates one run. With streaming stores, whole cache lines of dst (8 nodes, aligned because the stride is a
/// multiple of 8 and the arrays are 64-byte aligned) are computed into an L1 buffer and stored non-temporally;
/// the unaligned head and tail of the run use ordinary stores.
template <bool kForceField, bool kRegularized>
void update_run(const StreamCollideArgs& a, const TrtRates& rates, const std::array<const double*, C::q>& pull,
                const std::array<double*, C::q>& out, std::ptrdiff_t begin, std::ptrdiff_t end) {
#if defined(__AVX512F__)
  if (a.streaming_stores) {
    constexpr std::ptrdiff_t kLine = 8;
    const std::ptrdiff_t head_end = std::min(end, (begin + kLine - 1) / kLine * kLine);
    update_nodes<kForceField, kRegularized>(a, rates, pull, out, 0, begin, head_end);
    alignas(64) double buf[C::q][kLine];
    std::array<double*, C::q> rows{};
    for (std::size_t k = 0; k < C::q; ++k) rows[k] = buf[k];
    std::ptrdiff_t n = head_end;
    for (; n + kLine <= end; n += kLine) {
      update_nodes<kForceField, kRegularized>(a, rates, pull, rows, n, n, n + kLine);
      for (std::size_t k = 0; k < C::q; ++k) _mm512_stream_pd(out[k] + n, _mm512_load_pd(buf[k]));
    }
    update_nodes<kForceField, kRegularized>(a, rates, pull, out, 0, n, end);
    return;
  }
#endif
  update_nodes<kForceField, kRegularized>(a, rates, pull, out, 0, begin, end);
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
  const TrtRates bulk = trt_rates(a.omega_plus, a.omega_minus);
  const TrtRates inner = a.inner != nullptr ? trt_rates(a.inner->omega_plus, a.inner->omega_minus) : bulk;
#pragma omp parallel if (a.threaded)
  {
#pragma omp for schedule(static)
    for (std::ptrdiff_t r = 0; r < runs; ++r) {
      const FluidRun run = a.runs[static_cast<std::size_t>(r)];
      const std::ptrdiff_t end = run.begin + run.length;
      const bool in = a.inner != nullptr && run.phase != 0;
      const TrtRates& rates = in ? inner : bulk;
      if (in ? a.inner->regularized : a.regularized) {
        if (has_field) {
          update_run<true, true>(a, rates, pull, out, run.begin, end);
        } else {
          update_run<false, true>(a, rates, pull, out, run.begin, end);
        }
      } else if (has_field) {
        update_run<true, false>(a, rates, pull, out, run.begin, end);
      } else {
        update_run<false, false>(a, rates, pull, out, run.begin, end);
      }
    }
#if defined(__AVX512F__)
    _mm_sfence();   // order this thread's streaming stores before the next pass reads dst
#endif
  }
}

}  // namespace hs::resolved
