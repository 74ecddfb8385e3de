// SPDX-License-Identifier: MIT
// The in-place AA-pattern stream + TRT/BGK collision kernel with Guo forcing.
#include "resolved/lbm/aa_stream_collide.hpp"

#include "resolved/lbm/trt_guo_collision.hpp"

namespace hs::resolved {
namespace {

using C = D3Q19;

/// The 19 slot arrays one node reads and writes: node n reads its f_i from and writes its f*_i to slot[j][n] for a
/// direction j fixed by the step (see slot_of). The reads and writes of a node go through the same 19 pointers
/// (neighbour step: f_i from A[opp(i)][n - c_i] = slot[opp(i)][n], f*_i to A[i][n + c_i] = slot[i][n]; local step:
/// f_i from A[i][n] = slot[i][n], f*_i to A[opp(i)][n] = slot[opp(i)][n]), which halves the live pointers of the
/// loop against separate read and write tables (38 do not fit in the 16 general registers).
using Slots = std::array<double*, C::q>;

/// The slot array holding f_i (kRead) or receiving f*_i (!kRead) in step kStep.
template <AaStep kStep, bool kRead>
constexpr std::size_t slot_of(int i) {
  const bool own = (kStep == AaStep::neighbour) != kRead;
  return static_cast<std::size_t>(own ? i : C::opposite(i));
}

/// Updates nodes [begin, end): f_i = slot[slot_of<kStep, true>(i)][n], collide, store f*_i to
/// slot[slot_of<kStep, false>(i)][n]. The SIMD pragma is valid because node n's slots are disjoint from every other
/// node's (see the header), and each store depends on all 19 loads of its own node.
template <AaStep kStep, bool kForceField>
void aa_update_nodes(const AaStreamCollideArgs& a, const Slots& slot, std::ptrdiff_t begin, std::ptrdiff_t end) {
  const TrtRates rates = trt_rates(a.omega_plus, a.omega_minus);
  const std::ptrdiff_t vol = static_cast<std::ptrdiff_t>(a.force_stride);
#pragma omp simd
  for (std::ptrdiff_t n = begin; n < end; ++n) {
    double f[C::q];
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) f[i] = slot[slot_of<kStep, true>(i)][n];
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
    for (int i = 0; i < C::q; ++i) slot[slot_of<kStep, false>(i)][n] = post[i];
  }
}

/// Slot tables of the neighbour step for a node at the low (x = 0) and/or high (x = nx - 1) end of a periodic row:
/// the directions that cross the face read and write the image at the other end instead of the ghost. slot[j][n]
/// is A[j][n + c_j]: it lies beyond the low face for c_jx = -1 and beyond the high face for c_jx = +1.
Slots edge_slots(const Slots& slot, std::ptrdiff_t nx, bool low, bool high) {
  Slots t = slot;
  for (std::size_t j = 0; j < C::q; ++j) {
    const int cx = C::c[j][0];
    if (low && cx == -1) t[j] += nx;
    if (high && cx == 1) t[j] -= nx;
  }
  return t;
}

template <AaStep kStep, bool kForceField>
void aa_update_run(const AaStreamCollideArgs& a, const Slots& slot, const std::array<Slots, 3>& edges, FluidRun run) {
  std::ptrdiff_t begin = run.begin;
  std::ptrdiff_t end = run.begin + run.length;
  if (kStep == AaStep::neighbour && a.wrap_x > 0) {
    const std::ptrdiff_t ghost = (a.stride_y - a.wrap_x) / 2;
    const std::ptrdiff_t x0 = begin % a.stride_y - ghost;
    const bool low = x0 == 0;
    const bool high = x0 + run.length == a.wrap_x;
    if (low && high && run.length == 1) {
      aa_update_nodes<kStep, kForceField>(a, edges[2], begin, begin + 1);
      return;
    }
    if (low) {
      aa_update_nodes<kStep, kForceField>(a, edges[0], begin, begin + 1);
      ++begin;
    }
    if (high) {
      aa_update_nodes<kStep, kForceField>(a, edges[1], end - 1, end);
      --end;
    }
  }
  aa_update_nodes<kStep, kForceField>(a, slot, begin, end);
}

template <AaStep kStep>
void aa_update_runs(const AaStreamCollideArgs& a) {
  Slots slot{};
  for (std::size_t j = 0; j < C::q; ++j) {
    slot[j] = a.f + j * a.volume + (kStep == AaStep::neighbour ? a.offset[j] : 0);
  }
  // The local step touches only the node itself: no wrapping.
  const std::ptrdiff_t nx = kStep == AaStep::neighbour ? a.wrap_x : 0;
  const std::array<Slots, 3> edges{edge_slots(slot, nx, true, false), edge_slots(slot, nx, false, true),
                                   edge_slots(slot, nx, true, true)};
  const auto runs = static_cast<std::ptrdiff_t>(a.runs.size());
  const bool has_field = a.force_field != nullptr;
#pragma omp parallel for schedule(static) if (a.threaded)
  for (std::ptrdiff_t r = 0; r < runs; ++r) {
    const FluidRun run = a.runs[static_cast<std::size_t>(r)];
    if (has_field) {
      aa_update_run<kStep, true>(a, slot, edges, run);
    } else {
      aa_update_run<kStep, false>(a, slot, edges, run);
    }
  }
}

}  // namespace

void aa_stream_collide(const AaStreamCollideArgs& a, AaStep step) {
  if (step == AaStep::local) {
    aa_update_runs<AaStep::local>(a);
  } else {
    aa_update_runs<AaStep::neighbour>(a);
  }
}

}  // namespace hs::resolved
