// SPDX-License-Identifier: MIT
// The fused pull-stream + TRT/BGK collision kernel with Guo forcing: the bulk loop of the fluid solver.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "common/vec3.hpp"
#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

/// A run of consecutive fluid nodes along x: linear indices [begin, begin + length).
struct FluidRun {
  std::ptrdiff_t begin;
  std::ptrdiff_t length;
  /// AA: >= 0 when the kernel keeps the pre-collision odd parts of these nodes for their wall links: node begin + k
  /// is entry odd_parts + k of AaStreamCollideArgs::odd_parts. -1: none.
  std::ptrdiff_t odd_parts = -1;
  /// 0: the bulk fluid; 1: the inner phase (the cytoplasm inside a cell), which relaxes with the kernel's `inner`
  /// rates. A run holds nodes of one phase only (FluidLattice splits the runs where the phase changes).
  std::uint8_t phase = 0;
};

/// The relaxation of one fluid phase: the rates of trt_guo_collide and whether the regularised kernel runs
/// (CollisionParams::omega_plus, omega_minus, regularizes).
struct PhaseRelaxation {
  double omega_plus;
  double omega_minus;
  bool regularized;
};

struct StreamCollideArgs {
  const double* src;                             // post-collision populations of step t (SoA, stride volume)
  double* dst;                                   // receives post-collision populations of step t+1
  std::size_t volume;                            // component stride of src/dst, a multiple of 8 (cache lines)
  std::array<std::ptrdiff_t, D3Q19::q> offset;   // linear offset of c_i
  std::span<const FluidRun> runs;                // the fluid nodes to update
  common::Vec3 body_force;                       // uniform force density, lattice units
  const double* force_field;                     // per-node force density (3 comps, stride force_stride) or nullptr
  std::size_t force_stride;                      // component stride of force_field
  double omega_plus;                             // 1/tau+
  double omega_minus;                            // 1/tau- (= omega_plus for BGK; unused when regularized)
  bool regularized;                              // regularised collision (regularized_guo_collision.hpp)
  bool streaming_stores;                         // write dst with non-temporal stores (arrays far beyond cache)
  bool threaded;                                 // share the runs among OpenMP threads
  /// Runs with FluidRun::phase == 1 relax with these instead (a viscosity of their own); nullptr: every run relaxes
  /// with omega_plus, omega_minus, regularized, and the kernel is the single-phase one bit for bit.
  const PhaseRelaxation* inner = nullptr;
};

/// One lattice Boltzmann step on every node of `runs` (with `inner`, the runs of phase 1 with their own rates):
///   pull:    f_i(x) = f*_i(x - c_i)                                  (src)
///   moments: rho = sum f_i,  u = (sum f_i c_i + F/2) / rho           (Guo et al. 2002)
///   TRT:     f*_i = f_i - w+ (f+_i - f+eq_i) - w- (f-_i - f-eq_i) + (1 - w+/2) S+_i + (1 - w-/2) S-_i
/// with f+-_i = (f_i +- f_-i)/2, the Guo source split into its even part S+_i = w_i [9 (c.u)(c.F) - 3 u.F] and odd
/// part S-_i = 3 w_i c.F (Ginzburg et al. 2008; Krueger et al. 2017, sections 6.3 and 10.7). BGK is w- = w+.
/// pre:  src is complete on every node any run pulls from: ghosts exchanged, wall and open-boundary slots set.
/// post: dst holds post-collision populations on the run nodes; other nodes of dst are untouched.
/// Memory traffic per node: 19 loads + 19 stores of doubles (plus 3 loads with a force field); no branches.
/// With streaming_stores (AVX-512 builds), cache-line-aligned groups of 8 nodes are stored non-temporally, which
/// saves the write-allocate read of dst (19 x 8 bytes per node); pre: src and dst 64-byte aligned.
void stream_collide(const StreamCollideArgs& args);

}  // namespace hs::resolved
