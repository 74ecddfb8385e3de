// SPDX-License-Identifier: MIT
// Sparse boundary passes of the pull scheme: wall links (half-way and Bouzidi bounce-back) and open faces.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "common/vec3.hpp"

namespace hs::resolved {

/// How links that cross a wall of the Shape are closed.
enum class WallRule {
  half_way,   // wall assumed half way along every cut link (exact for planar walls on the lattice midplanes)
  bouzidi     // linear interpolated bounce-back with the exact wall fraction q of each link
};

/// One link from fluid node x along c_i that crosses a wall. The pull at x for direction -i reads slot
/// (target = x + c_i, -i); the wall pass writes there, before the bulk kernel:
///   value = a f*_i(x) + b f*_i(x - c_i) + c f*_-i(x) + d + e [ (f_i(x) - f_-i(x))/2 - (f*_i(x) - f*_-i(x))/2 ]
/// where f are the pre-collision populations of x (read from the previous buffer) and f* the post-collision ones.
/// Half-way bounce-back: a = 1, b = c = 0, d = -2 w_i rho_w (c_i . u_w) / c_s^2 (moving wall, Ladd 1994).
/// Bouzidi, Firdaouss & Lallemand 2001 (Phys. Fluids 13:3452), linear, q = wall fraction along the link:
///   q <  1/2: a = 2q, b = 1 - 2q, c = 0, d as half-way;   q >= 1/2: a = 1/(2q), b = 0, c = (2q-1)/(2q), d / (2q)
/// (Krueger et al. 2017, section 11.3.3). With q < 1/2 and x - c_i not fluid, it falls back to half-way.
/// Plain linear Bouzidi is not parametrised by the TRT magic number alone. Our steady-state analysis of the TRT
/// recurrence for a quadratic velocity field (in the spirit of Ginzburg, Verhaeghe & d'Humieres 2008, Commun.
/// Comput. Phys. 3:427) gives for the link closure, with u the half-force velocity, d = c_i . grad:
///   u - q du + [Lambda + Lambda+ (1/2 - q)] d^2u - (Lambda/3) lap u = 0        (Lambda+ = tau+ - 1/2),
/// so the wall moves with tau (measured, plane channel at q = 0.25: 0.16 % error at tau = 1, 3.7 % at tau = 4).
/// At steady state the odd part of (f - f*) at x equals Lambda+ d^2u (per link weight), so adding e times it, with
///   e = 2q - 1 + (q^2 - 4 Lambda/3) / Lambda+            (q < 1/2)
///   e = [1 - 2q + (q^2 - 4 Lambda/3) / Lambda+] / (2q)   (q >= 1/2)
/// turns the closure into u - q du + q^2/2 d^2u + (Lambda/3)(d^2u - lap u) = 0: independent of tau at fixed Lambda,
/// exact for planar walls at any q (verified to round-off in a channel for q in 0.02..0.9, tau in 0.6..4) and
/// second order for curved ones. The amplification 1/Lambda+ asks for tau not too close to 1/2 (tested >= 0.6).
/// Lambda shift: the remaining term (Lambda/3)(d^2u - lap u) vanishes for planar walls only; around a tube at Lambda =
/// (tau - 1/2)/2 (the regularised collision) it slows the centre line by 22 % at tau 60, R = 10. To close as TRT at
/// Lambda0 = lambda_closure, add -((Lambda - Lambda0)/3)(d^2u - lap u): d^2u from the same odd part (e grows by
/// -2 (Lambda - Lambda0) / (3 Lambda+), divided by 2q for q >= 1/2), lap u from the steady Stokes balance
/// rho nu lap u = grad p - F with nu = Lambda+/3: d grows by -6 w_i (Lambda - Lambda0) c_i.F / (rho Lambda+) (over 2q
/// for q >= 1/2; WallLink::force_coef, applied with the body force of each pass). The pressure gradient is left out
/// (exact for force-driven flows such as the periodic campaign tube), and so is the IBM force field (only the uniform
/// body force enters).
struct WallLink {
  std::ptrdiff_t target;   // linear index of x + c_i
  std::ptrdiff_t node;     // linear index of x
  std::ptrdiff_t second;   // linear index of x - c_i (= node when b = 0)
  std::ptrdiff_t behind;   // linear index of x - c_i, where the pre-collision f_i(x) comes from
  int dir;                 // i, pointing from the fluid into the wall
  double a, b, c, d, e;
  /// AA, e != 0: where the pre-collision odd part of x's pair (k, k + 9) holding i is kept (see
  /// AaStreamCollideArgs::odd_parts); the link's own (f_i - f_-i)/2 is that value, negated when i > 9.
  std::ptrdiff_t odd_slot = -1;
  /// Lambda shift only: the value also gets force_coef . F, F the uniform body force at the time of the pass.
  common::Vec3 force_coef;
};

/// What make_wall_link needs to know about one cut link.
struct LinkSpec {
  std::ptrdiff_t node;        // x
  std::ptrdiff_t target;      // x + c_i
  std::ptrdiff_t second;      // x - c_i
  bool second_usable;         // x - c_i holds valid populations (fluid or open boundary)
  int dir;                    // i
  double q;                   // wall fraction along the link (Bouzidi)
  bool interpolated;          // Bouzidi with the correction above; false = plain half-way bounce-back
  common::Vec3 wall_velocity_lu;
  double rho_wall_lu;
  double lambda_plus;         // tau+ - 1/2
  double lambda;              // (tau+ - 1/2)(tau- - 1/2)
  /// The Lambda whose wall location the closure reproduces (CollisionParams::closure_lambda); = lambda: the closure
  /// above. Otherwise see the Lambda shift below.
  double lambda_closure;
};

WallLink make_wall_link(const LinkSpec& spec);

/// Writes the bounce-back values of every link into `src` (post-collision populations, component stride
/// `volume`); `previous` is the buffer of the step before (post-collision f* of t-1, complete), from which the
/// pre-collision f(x, t) is pulled. pre: ghosts of src exchanged and open-boundary nodes set. post: every slot a
/// fluid node pulls from across a wall holds its bounce-back value.
/// `body_force`: the uniform force density, for links with a force_coef (nullptr: none has one).
void apply_wall_links(std::span<const WallLink> links, double* src, const double* previous, std::size_t volume,
                      const common::Vec3* body_force = nullptr);

/// Where the AA pattern keeps f*_j(y): A[opp(j)][y] in the swapped layout, A[j][y + c_j] in the natural one
/// (see aa_stream_collide.hpp); with wrap_x > 0 the node index is first wrapped into the block along x (the kernel
/// then keeps no x ghosts).
struct AaLayout {
  bool natural;
  std::size_t volume;                                  // component stride
  const std::ptrdiff_t* offset;                        // linear offsets of the 19 directions
  std::ptrdiff_t wrap_x = 0;                           // as AaStreamCollideArgs::wrap_x
  std::ptrdiff_t stride_y = 0;
  [[nodiscard]] std::size_t slot(int j, std::ptrdiff_t y) const;
};

/// The pre-collision odd part of each link's node and pair for the coming step (see WallLink::odd_slot), read from
/// the complete state before it. The AA kernel keeps them itself during a step; this serves the first one.
void capture_link_odd_parts(std::span<const WallLink> links, const double* f, const AaLayout& layout,
                            std::span<double> odd_parts);

/// A wall link resolved for one AA layout (the layout alternates with the step): the slots of its four accesses and
/// its coefficients in one record. Along a wrapped x each slot costs a modulo; these are computed once, not per step
/// (the per-step slot arithmetic took about half the time of the links' pass).
struct AaWallLink {
  std::size_t post_i;        // f*_i(x)
  std::size_t post_o;        // f*_-i(x)
  std::size_t second;        // f*_i(x - c_i), read where b != 0
  std::size_t target;        // written: the slot x + c_i pulls f_-i from
  double a, b, c, d, e;      // as WallLink
  std::ptrdiff_t odd_slot;   // as WallLink::odd_slot
  common::Vec3 force_coef;   // as WallLink::force_coef
  bool odd_negated;          // i > D3Q19::half: the link's own odd part is its pair's, negated
};

/// The links in `layout`'s slots, in the same order.
std::vector<AaWallLink> resolve_aa_links(std::span<const WallLink> links, const AaLayout& layout);

/// apply_wall_links for the single AA buffer: the same values, written to and read from the links' resolved slots.
/// `odd_parts`: the pre-collision odd parts of the step just made, at the links' odd_slot (read where e != 0).
void apply_wall_links_aa(std::span<const AaWallLink> links, double* f, std::span<const double> odd_parts,
                         const common::Vec3* body_force = nullptr);

/// A ghost node on an open face, set by non-equilibrium extrapolation (Guo, Zheng & Shi 2002, Chinese Phys.
/// 11:366): f*_i(ghost) = f^eq_i(rho_b, u_b) + [f*_i(inner) - f^eq_i(rho*, u*)(inner)], where rho*, u* are the
/// moments of the inner node's post-collision populations. Velocity inlet: u_b given, rho_b = rho*(inner).
/// Pressure outlet: rho_b given (p = c_s^2 rho), u_b = u*(inner).
struct OpenNode {
  std::ptrdiff_t ghost;
  std::ptrdiff_t inner;
  bool velocity_given;
  common::Vec3 u_lu;
  double rho_lu;
};

/// pre: ghosts of src exchanged. post: all 19 populations of every open ghost node are set.
void apply_open_boundaries(std::span<const OpenNode> nodes, double* src, std::size_t volume);

}  // namespace hs::resolved
