// SPDX-License-Identifier: MIT
// Sparse boundary passes of the pull scheme: wall links (half-way and Bouzidi bounce-back) and open faces.
#pragma once

#include <cstddef>
#include <span>

#include "common/vec3.hpp"

namespace hs::resolved {

/// How links that cross a wall of the Shape are closed.
enum class WallRule {
  half_way,   // wall assumed half way along every cut link (exact for planar walls on the lattice midplanes)
  bouzidi     // linear interpolated bounce-back with the exact wall fraction q of each link
};

/// One link from fluid node x along c_i that crosses a wall. The pull at x for direction -i reads slot
/// (target = x + c_i, -i); the wall pass writes there, before the bulk kernel:
///   value = a f*_i(x) + b f*_i(x - c_i) + c f*_-i(x) + d
/// Half-way bounce-back: a = 1, b = c = 0, d = -2 w_i rho_w (c_i . u_w) / c_s^2 (moving wall, Ladd 1994).
/// Bouzidi, Firdaouss & Lallemand 2001 (Phys. Fluids 13:3452), linear, q = wall fraction along the link:
///   q <  1/2: a = 2q, b = 1 - 2q, c = 0, d as half-way;   q >= 1/2: a = 1/(2q), b = 0, c = (2q-1)/(2q), d / (2q)
/// (Krueger et al. 2017, section 11.3.3). With q < 1/2 and x - c_i not fluid, it falls back to half-way.
/// Caveat (measured): linear Bouzidi is not parametrised by the TRT magic number alone; at q != 1/2 its steady
/// error grows with tau at fixed Lambda (plane channel, q = 0.25: 0.16 % at tau = 1, 1.1 % at tau = 2, 3.7 % at
/// tau = 4; tube R = 10: 0.17 % at tau = 1, 0.92 % at tau = 2). Keep tau near 1 where wall accuracy matters.
struct WallLink {
  std::ptrdiff_t target;   // linear index of x + c_i
  std::ptrdiff_t node;     // linear index of x
  std::ptrdiff_t second;   // linear index of x - c_i (= node when b = 0)
  int dir;                 // i, pointing from the fluid into the wall
  double a, b, c, d;
};

/// Builds the link of fluid node `node` along direction `dir` with wall fraction q (1/2 for half-way).
/// `second_usable` says whether x - c_i holds valid post-collision populations (fluid or open boundary).
WallLink make_wall_link(std::ptrdiff_t node, std::ptrdiff_t target, std::ptrdiff_t second, bool second_usable,
                        int dir, double q, const common::Vec3& wall_velocity_lu, double rho_wall_lu);

/// Writes the bounce-back values of every link into `src` (post-collision populations, component stride
/// `volume`). pre: ghosts of src exchanged and open-boundary nodes set. post: every slot a fluid node pulls
/// from across a wall holds its bounce-back value.
void apply_wall_links(std::span<const WallLink> links, double* src, std::size_t volume);

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
