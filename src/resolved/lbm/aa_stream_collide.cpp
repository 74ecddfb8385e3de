// SPDX-License-Identifier: MIT
// The in-place AA-pattern stream + TRT/BGK collision kernel with Guo forcing.
#include "resolved/lbm/aa_stream_collide.hpp"

#include "resolved/lbm/trt_guo_collision.hpp"

namespace hs::resolved {
namespace {

using C = D3Q19;

/// Updates nodes [begin, end): f_i = in[i][n], collide, out[i][n] = f*_i. `in` and `out` point into the same
/// buffer; the SIMD pragma is valid because node n's slots are disjoint from every other node's (see the header),
/// and each store depends on all 19 loads of its own node.
template <bool kForceField>
void aa_update_nodes(const AaStreamCollideArgs& a, const std::array<const double*, C::q>& in,
                     const std::array<double*, C::q>& out, std::ptrdiff_t begin, std::ptrdiff_t end) {
  const TrtRates rates = trt_rates(a.omega_plus, a.omega_minus);
  const std::ptrdiff_t vol = static_cast<std::ptrdiff_t>(a.force_stride);
#pragma omp simd
  for (std::ptrdiff_t n = begin; n < end; ++n) {
    double f[C::q];
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) f[i] = in[static_cast<std::size_t>(i)][n];
    double fx = a.body_force.x;
    double fy = a.body_force.y;
    double fz = a.body_force.z;
    if constexpr (kForceField) {
      fx += a.force_field[n];
      fy += a.force_field[vol + n];
      fz += a.force_field[2 * vol + n];
    }
    double post[C::q];
    trt_guo_collide(f, fx, fy, fz, rates, post);
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) out[static_cast<std::size_t>(i)][n] = post[i];
  }
}

}  // namespace

void aa_stream_collide(const AaStreamCollideArgs& a, AaStep step) {
  std::array<const double*, C::q> in{};
  std::array<double*, C::q> out{};
  for (std::size_t i = 0; i < C::q; ++i) {
    const auto o = static_cast<std::size_t>(C::opposite(static_cast<int>(i)));
    if (step == AaStep::local) {
      in[i] = a.f + i * a.volume;
      out[i] = a.f + o * a.volume;
    } else {
      in[i] = a.f + o * a.volume - a.offset[i];
      out[i] = a.f + i * a.volume + a.offset[i];
    }
  }
  const auto runs = static_cast<std::ptrdiff_t>(a.runs.size());
  const bool has_field = a.force_field != nullptr;
#pragma omp parallel for schedule(static) if (a.threaded)
  for (std::ptrdiff_t r = 0; r < runs; ++r) {
    const FluidRun run = a.runs[static_cast<std::size_t>(r)];
    if (has_field) {
      aa_update_nodes<true>(a, in, out, run.begin, run.begin + run.length);
    } else {
      aa_update_nodes<false>(a, in, out, run.begin, run.begin + run.length);
    }
  }
}

}  // namespace hs::resolved
