// SPDX-License-Identifier: MIT
// The in-place AA-pattern stream + TRT/BGK collision kernel with Guo forcing (one population buffer).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "resolved/lbm/d3q19.hpp"
#include "resolved/lbm/stream_collide.hpp"

namespace hs::resolved {

/// The two alternating steps of the AA pattern (Bailey, Myre, Walsh, Lilja & Saar 2009, Proc. ICPP, "Accelerating
/// lattice Boltzmann fluid flow simulations using graphics processors"). One buffer A holds every post-collision
/// population f*_j(y) exactly once, in one of two layouts:
///   swapped layout (after a local step):      f*_j(y) at A[opp(j)][y]
///   natural layout (after a neighbour step):  f*_j(y) at A[j][y + c_j], i.e. A[i][x] = f_i(x), pre-collision
/// local step     (natural -> swapped):   f_i(x) = A[i][x];            collide; A[opp(i)][x]   = f*_i(x)
/// neighbour step (swapped -> natural):   f_i(x) = A[opp(i)][x - c_i]; collide; A[i][x + c_i]  = f*_i(x)
/// Each node reads and writes the same 19 slots and no two nodes share a slot, so the update is in place, needs no
/// second buffer and moves 19 loads + 19 stores of doubles per node with no write-allocate traffic (the stored
/// lines were just read). The neighbour step reads and writes the ghost layer; the local step touches only x.
enum class AaStep { local, neighbour };

/// The two calls of AaStreamCollideArgs::after_layers for layer z: once z - 1 and z are updated (with_below), and
/// once z and z + 1 are (with_above).
enum class LayerPair { with_below, with_above };

struct AaStreamCollideArgs {
  double* f;                                     // the single population buffer (SoA, stride volume)
  std::size_t volume;                            // component stride of f
  std::array<std::ptrdiff_t, D3Q19::q> offset;   // linear offset of c_i
  std::span<const FluidRun> runs;                // the fluid nodes to update
  common::Vec3 body_force;                       // uniform force density, lattice units
  const double* force_field;                     // per-node force density (3 comps, stride force_stride) or nullptr
  std::size_t force_stride;                      // component stride of force_field
  double omega_plus;                             // 1/tau+
  double omega_minus;                            // 1/tau- (= omega_plus for BGK; unused when regularized)
  bool regularized;                              // regularised collision (regularized_guo_collision.hpp)
  bool threaded;                                 // share the runs among OpenMP threads
  /// > 0: x is periodic within this block of wrap_x interior nodes, and the neighbour step wraps its x reads and
  /// writes into the interior instead of using the x ghosts (no x fill or fold needed). 0: no wrapping.
  std::ptrdiff_t wrap_x = 0;
  std::ptrdiff_t stride_y = 0;                   // linear offset of one node along y (with wrap_x > 0)
  /// Optional layering along z: the runs of local layer z are runs[layer_runs[z] .. layer_runs[z + 1]) (size n_z + 1;
  /// empty: no layering). The threads then take contiguous ranges of layers (balanced by nodes) and call the hook,
  /// concurrently for different layers, so sparse passes can work on layers while they are still in cache: once
  /// per layer z and LayerPair (see there).
  const std::vector<std::size_t>* layer_runs = nullptr;
  const std::function<void(int, LayerPair)>* after_layers = nullptr;
  /// Where runs with FluidRun::odd_parts >= 0 leave the pre-collision odd parts (f_k - f_{k+9})/2, k = 1..9, of their
  /// nodes: entry e of pair k at odd_parts[(k - 1) * odd_stride + e]. The wall links need them after the step
  /// (apply_wall_links_aa); the kernel has them in registers, where a separate pass would reread them from memory.
  double* odd_parts = nullptr;
  std::size_t odd_stride = 0;
  /// As StreamCollideArgs::inner: the relaxation of the runs with FluidRun::phase == 1; nullptr: one phase.
  const PhaseRelaxation* inner = nullptr;
};

/// One AA step on every node of `runs`, with the same collision (trt_guo_collide) as stream_collide().
/// pre:  local step: f in the natural layout on the run nodes. Neighbour step: f in the swapped layout on every
///       node the runs pull from (ghosts filled, wall slots set).
/// post: the other layout on the run nodes; the neighbour step also writes the slots A[i][x + c_i] that lie on
///       ghost or solid nodes (to be folded to their owners or bounced back). With wrap_x, x +- 1 beyond the block
///       means the node at the other end of the row (the periodic image) in both reads and writes.
void aa_stream_collide(const AaStreamCollideArgs& args, AaStep step);

}  // namespace hs::resolved
