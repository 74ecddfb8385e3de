// SPDX-License-Identifier: MIT
// Sparse boundary passes of the pull scheme: wall links and open faces.
#include "resolved/lbm/boundary_links.hpp"

#include "resolved/lbm/d3q19.hpp"
#include "resolved/lbm/equilibrium.hpp"

namespace hs::resolved {

WallLink make_wall_link(std::ptrdiff_t node, std::ptrdiff_t target, std::ptrdiff_t second, bool second_usable,
                        int dir, double q, const common::Vec3& wall_velocity_lu, double rho_wall_lu) {
  const auto& c = D3Q19::c[static_cast<std::size_t>(dir)];
  const double cu = c[0] * wall_velocity_lu.x + c[1] * wall_velocity_lu.y + c[2] * wall_velocity_lu.z;
  const double d = -2.0 * D3Q19::w[static_cast<std::size_t>(dir)] * rho_wall_lu * cu / D3Q19::cs2;
  WallLink l{.target = target, .node = node, .second = node, .dir = dir, .a = 1.0, .b = 0.0, .c = 0.0, .d = d};
  if (q == 0.5 || (q < 0.5 && !second_usable)) return l;
  if (q < 0.5) {
    l.a = 2.0 * q;
    l.b = 1.0 - 2.0 * q;
    l.second = second;
  } else {
    l.a = 1.0 / (2.0 * q);
    l.c = (2.0 * q - 1.0) / (2.0 * q);
    l.d = d / (2.0 * q);
  }
  return l;
}

void apply_wall_links(std::span<const WallLink> links, double* src, std::size_t volume) {
  const auto n = static_cast<std::ptrdiff_t>(links.size());
  const auto vol = static_cast<std::ptrdiff_t>(volume);
  // Each link costs a few memory accesses: only tens of thousands of them are worth a parallel region.
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const WallLink& l = links[static_cast<std::size_t>(k)];
    const std::ptrdiff_t i = l.dir;
    const std::ptrdiff_t o = D3Q19::opposite(l.dir);
    src[o * vol + l.target] = l.a * src[i * vol + l.node] + l.b * src[i * vol + l.second] +
                              l.c * src[o * vol + l.node] + l.d;
  }
}

void apply_open_boundaries(std::span<const OpenNode> nodes, double* src, std::size_t volume) {
  const auto vol = static_cast<std::ptrdiff_t>(volume);
  for (const OpenNode& b : nodes) {
    Populations f{};
    for (std::ptrdiff_t i = 0; i < D3Q19::q; ++i) f[static_cast<std::size_t>(i)] = src[i * vol + b.inner];
    const NodeMoments inner = moments(f, common::Vec3{});
    const double rho_b = b.velocity_given ? inner.rho : b.rho_lu;
    const common::Vec3 u_b = b.velocity_given ? b.u_lu : inner.u;
    for (int i = 0; i < D3Q19::q; ++i) {
      src[i * vol + b.ghost] = equilibrium(i, rho_b, u_b) + f[static_cast<std::size_t>(i)] - equilibrium(i, inner.rho, inner.u);
    }
  }
}

}  // namespace hs::resolved
