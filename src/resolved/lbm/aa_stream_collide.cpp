// SPDX-License-Identifier: MIT
// The in-place AA-pattern stream + TRT/BGK collision kernel with Guo forcing.
#include "resolved/lbm/aa_stream_collide.hpp"

#include <omp.h>

#include <vector>

#include "resolved/lbm/regularized_guo_collision.hpp"
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
/// node's (see the header), and each store depends on all 19 loads of its own node. kOddParts: also keep the node's
/// pre-collision odd parts at entry odd_base + n (see AaStreamCollideArgs::odd_parts).
template <AaStep kStep, bool kForceField, bool kOddParts, bool kRegularized>
void aa_update_nodes(const AaStreamCollideArgs& a, const TrtRates& rates, const Slots& slot, std::ptrdiff_t begin,
                     std::ptrdiff_t end, std::ptrdiff_t odd_base) {
  const std::ptrdiff_t vol = static_cast<std::ptrdiff_t>(a.force_stride);
  const auto odd_stride = static_cast<std::ptrdiff_t>(a.odd_stride);
  const auto update = [&](std::ptrdiff_t n) __attribute__((always_inline)) {
    double f[C::q];
#pragma GCC unroll 19
    for (int i = 0; i < C::q; ++i) f[i] = slot[slot_of<kStep, true>(i)][n];
    if constexpr (kOddParts) {
#pragma GCC unroll 9
      for (int k = 1; k <= C::half; ++k) a.odd_parts[(k - 1) * odd_stride + odd_base + n] = 0.5 * (f[k] - f[k + C::half]);
    }
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
    for (int i = 0; i < C::q; ++i) slot[slot_of<kStep, false>(i)][n] = post[i];
  };
  if constexpr (kOddParts) {
    // The nodes along walls come in runs of one to three: a plain loop, without the SIMD set-up.
    for (std::ptrdiff_t n = begin; n < end; ++n) update(n);
  } else {
#pragma omp simd
    for (std::ptrdiff_t n = begin; n < end; ++n) update(n);
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

template <AaStep kStep, bool kForceField, bool kOddParts, bool kRegularized>
void aa_update_run(const AaStreamCollideArgs& a, const TrtRates& rates, const Slots& slot,
                   const std::array<Slots, 3>& edges, FluidRun run) {
  std::ptrdiff_t begin = run.begin;
  std::ptrdiff_t end = run.begin + run.length;
  const std::ptrdiff_t odd_base = run.odd_parts - run.begin;
  if (kStep == AaStep::neighbour && a.wrap_x > 0) {
    const std::ptrdiff_t ghost = (a.stride_y - a.wrap_x) / 2;
    const std::ptrdiff_t x0 = begin % a.stride_y - ghost;
    const bool low = x0 == 0;
    const bool high = x0 + run.length == a.wrap_x;
    if (low && high && run.length == 1) {
      aa_update_nodes<kStep, kForceField, kOddParts, kRegularized>(a, rates, edges[2], begin, begin + 1, odd_base);
      return;
    }
    if (low) {
      aa_update_nodes<kStep, kForceField, kOddParts, kRegularized>(a, rates, edges[0], begin, begin + 1, odd_base);
      ++begin;
    }
    if (high) {
      aa_update_nodes<kStep, kForceField, kOddParts, kRegularized>(a, rates, edges[1], end - 1, end, odd_base);
      --end;
    }
  }
  aa_update_nodes<kStep, kForceField, kOddParts, kRegularized>(a, rates, slot, begin, end, odd_base);
}

struct RunKind {
  bool force_field;
  bool odd_parts;
  bool regularized;
};

/// The run's kernel instance for its kind.
template <AaStep kStep>
void aa_dispatch_run(const AaStreamCollideArgs& a, const TrtRates& rates, const Slots& slot,
                     const std::array<Slots, 3>& edges, FluidRun run, RunKind kind) {
  const auto with = [&]<bool kField, bool kOdd>() {
    if (kind.regularized) {
      aa_update_run<kStep, kField, kOdd, true>(a, rates, slot, edges, run);
    } else {
      aa_update_run<kStep, kField, kOdd, false>(a, rates, slot, edges, run);
    }
  };
  if (kind.force_field) {
    kind.odd_parts ? with.template operator()<true, true>() : with.template operator()<true, false>();
  } else {
    kind.odd_parts ? with.template operator()<false, true>() : with.template operator()<false, false>();
  }
}

struct LayerRange {
  int begin;
  int end;
};

/// This thread's contiguous range of layers: the layers whose first node falls in its equal share of the nodes
/// (`nodes_before[z]`: nodes in the layers below z; the last entry is the total).
LayerRange thread_layers(const std::vector<double>& nodes_before) {
  const int threads = omp_get_num_threads();
  const int t = omp_get_thread_num();
  const double total = nodes_before.back();
  const auto nz = static_cast<int>(nodes_before.size()) - 1;
  const auto first_at_or_above = [&](double share) {
    int z = 0;
    while (z < nz && nodes_before[static_cast<std::size_t>(z)] < share) ++z;
    return z;
  };
  if (t == threads - 1) return {first_at_or_above(total * t / threads), nz};
  return {first_at_or_above(total * t / threads), first_at_or_above(total * (t + 1) / threads)};
}

/// A run's first node starts 22 new streams (19 slots, 3 force components), whose first lines the hardware
/// prefetchers do not foresee: asking for those of a run a little ahead hides their latency.
constexpr std::size_t kPrefetchRuns = 3;

void prefetch_run_start(const AaStreamCollideArgs& a, const Slots& slot, std::ptrdiff_t n) {
  for (std::size_t j = 0; j < C::q; ++j) __builtin_prefetch(slot[j] + n, 1);
  if (a.force_field != nullptr) {
    const auto vol = static_cast<std::ptrdiff_t>(a.force_stride);
    for (std::ptrdiff_t k = 0; k < 3; ++k) __builtin_prefetch(a.force_field + k * vol + n);
  }
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
  const bool has_field = a.force_field != nullptr;
  const TrtRates rates = trt_rates(a.omega_plus, a.omega_minus);
  const TrtRates inner = a.inner != nullptr ? trt_rates(a.inner->omega_plus, a.inner->omega_minus) : rates;
  const auto update = [&](std::size_t r) {
    if (r + kPrefetchRuns < a.runs.size()) prefetch_run_start(a, slot, a.runs[r + kPrefetchRuns].begin);
    const FluidRun& run = a.runs[r];
    const bool odd_parts = run.odd_parts >= 0 && a.odd_parts != nullptr;
    const bool in = a.inner != nullptr && run.phase != 0;
    aa_dispatch_run<kStep>(a, in ? inner : rates, slot, edges, run,
                           RunKind{.force_field = has_field, .odd_parts = odd_parts,
                                   .regularized = in ? a.inner->regularized : a.regularized});
  };
  if (a.layer_runs == nullptr || a.layer_runs->empty()) {
    const auto runs = static_cast<std::ptrdiff_t>(a.runs.size());
#pragma omp parallel for schedule(static) if (a.threaded)
    for (std::ptrdiff_t r = 0; r < runs; ++r) update(static_cast<std::size_t>(r));
    return;
  }
  const std::vector<std::size_t>& layers = *a.layer_runs;
  const int nz = static_cast<int>(layers.size()) - 1;
  std::vector<double> nodes_before(layers.size(), 0.0);   // fluid nodes in the layers below z
  for (int z = 0; z < nz; ++z) {
    double n = 0.0;
    for (std::size_t r = layers[static_cast<std::size_t>(z)]; r < layers[static_cast<std::size_t>(z) + 1]; ++r) {
      n += static_cast<double>(a.runs[r].length);
    }
    nodes_before[static_cast<std::size_t>(z) + 1] = nodes_before[static_cast<std::size_t>(z)] + n;
  }
#pragma omp parallel if (a.threaded)
  {
    const LayerRange mine = thread_layers(nodes_before);
    for (int z = mine.begin; z < mine.end; ++z) {
      for (std::size_t r = layers[static_cast<std::size_t>(z)]; r < layers[static_cast<std::size_t>(z) + 1]; ++r) update(r);
      // Right after the update, while the layers are in cache; only (first, below) and (last, above) wait for
      // the layer of another thread.
      if (a.after_layers != nullptr && z > mine.begin) {
        (*a.after_layers)(z, LayerPair::with_below);
        (*a.after_layers)(z - 1, LayerPair::with_above);
      }
    }
#pragma omp barrier
    if (a.after_layers != nullptr && mine.end > mine.begin) {
      (*a.after_layers)(mine.begin, LayerPair::with_below);
      (*a.after_layers)(mine.end - 1, LayerPair::with_above);
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
