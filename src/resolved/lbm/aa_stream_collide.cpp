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

/// Pointer tables of the neighbour step for a node at the low (x = 0) and/or high (x = nx - 1) end of a periodic
/// row: the directions that cross the face read and write the image at the other end instead of the ghost.
struct EdgeTables {
  std::array<const double*, C::q> in;
  std::array<double*, C::q> out;
};

EdgeTables edge_tables(const std::array<const double*, C::q>& in, const std::array<double*, C::q>& out,
                       std::ptrdiff_t nx, bool low, bool high) {
  EdgeTables t{in, out};
  for (std::size_t i = 0; i < C::q; ++i) {
    const int cx = C::c[i][0];
    // Reads come from x - c_i, writes go to x + c_i.
    if (low && cx == 1) t.in[i] += nx;
    if (low && cx == -1) t.out[i] += nx;
    if (high && cx == -1) t.in[i] -= nx;
    if (high && cx == 1) t.out[i] -= nx;
  }
  return t;
}

template <bool kForceField>
void aa_update_run(const AaStreamCollideArgs& a, const std::array<const double*, C::q>& in,
                   const std::array<double*, C::q>& out, const std::array<EdgeTables, 3>& edges, FluidRun run) {
  std::ptrdiff_t begin = run.begin;
  std::ptrdiff_t end = run.begin + run.length;
  if (a.wrap_x > 0) {
    const std::ptrdiff_t ghost = (a.stride_y - a.wrap_x) / 2;
    const std::ptrdiff_t x0 = begin % a.stride_y - ghost;
    const bool low = x0 == 0;
    const bool high = x0 + run.length == a.wrap_x;
    if (low && high && run.length == 1) {
      aa_update_nodes<kForceField>(a, edges[2].in, edges[2].out, begin, begin + 1);
      return;
    }
    if (low) {
      aa_update_nodes<kForceField>(a, edges[0].in, edges[0].out, begin, begin + 1);
      ++begin;
    }
    if (high) {
      aa_update_nodes<kForceField>(a, edges[1].in, edges[1].out, end - 1, end);
      --end;
    }
  }
  aa_update_nodes<kForceField>(a, in, out, begin, end);
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
  AaStreamCollideArgs args = a;
  if (step == AaStep::local) args.wrap_x = 0;   // the local step touches only the node itself
  const std::array<EdgeTables, 3> edges{edge_tables(in, out, args.wrap_x, true, false),
                                        edge_tables(in, out, args.wrap_x, false, true),
                                        edge_tables(in, out, args.wrap_x, true, true)};
  const auto runs = static_cast<std::ptrdiff_t>(a.runs.size());
  const bool has_field = a.force_field != nullptr;
#pragma omp parallel for schedule(static) if (a.threaded)
  for (std::ptrdiff_t r = 0; r < runs; ++r) {
    const FluidRun run = a.runs[static_cast<std::size_t>(r)];
    if (has_field) {
      aa_update_run<true>(args, in, out, edges, run);
    } else {
      aa_update_run<false>(args, in, out, edges, run);
    }
  }
}

}  // namespace hs::resolved
