// SPDX-License-Identifier: MIT
// Sparse boundary passes of the pull scheme: wall links and open faces.
#include "resolved/lbm/boundary_links.hpp"

#include "resolved/lbm/d3q19.hpp"
#include "resolved/lbm/equilibrium.hpp"

namespace hs::resolved {

WallLink make_wall_link(const LinkSpec& s) {
  const auto& c = D3Q19::c[static_cast<std::size_t>(s.dir)];
  const common::Vec3& uw = s.wall_velocity_lu;
  const double cu = c[0] * uw.x + c[1] * uw.y + c[2] * uw.z;
  const double d = -2.0 * D3Q19::w[static_cast<std::size_t>(s.dir)] * s.rho_wall_lu * cu / D3Q19::cs2;
  WallLink l{.target = s.target, .node = s.node, .second = s.node, .behind = s.second, .dir = s.dir,
             .a = 1.0, .b = 0.0, .c = 0.0, .d = d, .e = 0.0, .odd_slot = -1, .force_coef = {}};
  const double q = s.q;
  if (!s.interpolated || (q < 0.5 && !s.second_usable)) return l;
  const double exactness = (q * q - 4.0 * s.lambda / 3.0) / s.lambda_plus;
  if (q < 0.5) {
    l.a = 2.0 * q;
    l.b = 1.0 - 2.0 * q;
    l.second = s.second;
    l.e = 2.0 * q - 1.0 + exactness;
  } else {
    l.a = 1.0 / (2.0 * q);
    l.c = (2.0 * q - 1.0) / (2.0 * q);
    l.d = d / (2.0 * q);
    l.e = (1.0 - 2.0 * q + exactness) / (2.0 * q);
  }
  if (s.lambda_closure != s.lambda) {
    // Lambda shift (see the header); the closure equation is scaled by 2q for q >= 1/2.
    const double scale = q < 0.5 ? 1.0 : 1.0 / (2.0 * q);
    const double shift = s.lambda - s.lambda_closure;
    l.e += scale * (-2.0 * shift / (3.0 * s.lambda_plus));
    const double fc = scale * (-6.0 * D3Q19::w[static_cast<std::size_t>(s.dir)] * shift / (s.rho_wall_lu * s.lambda_plus));
    l.force_coef = fc * common::Vec3{static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
  }
  return l;
}

void apply_wall_links(std::span<const WallLink> links, double* src, const double* previous, std::size_t volume,
                      const common::Vec3* body_force) {
  const auto n = static_cast<std::ptrdiff_t>(links.size());
  const auto vol = static_cast<std::ptrdiff_t>(volume);
  // Each link costs a few memory accesses: only tens of thousands of them are worth a parallel region.
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const WallLink& l = links[static_cast<std::size_t>(k)];
    const std::ptrdiff_t i = l.dir;
    const std::ptrdiff_t o = D3Q19::opposite(l.dir);
    const double post_i = src[i * vol + l.node];
    const double post_o = src[o * vol + l.node];
    const double odd_change = 0.5 * (previous[i * vol + l.behind] - previous[o * vol + l.target]) - 0.5 * (post_i - post_o);
    double value = l.a * post_i + l.b * src[i * vol + l.second] + l.c * post_o + l.d + l.e * odd_change;
    if (body_force != nullptr) value += dot(l.force_coef, *body_force);
    src[o * vol + l.target] = value;
  }
}

std::size_t AaLayout::slot(int j, std::ptrdiff_t y) const {
  const auto jj = static_cast<std::size_t>(j);
  std::ptrdiff_t node = natural ? y + offset[jj] : y;
  if (wrap_x > 0) {
    const std::ptrdiff_t x = node % stride_y - (stride_y - wrap_x) / 2;
    if (x < 0) node += wrap_x;
    if (x >= wrap_x) node -= wrap_x;
  }
  const std::size_t component = natural ? jj : static_cast<std::size_t>(D3Q19::opposite(j));
  return component * volume + static_cast<std::size_t>(node);
}

void capture_link_odd_parts(std::span<const WallLink> links, const double* f, const AaLayout& layout,
                            std::span<double> odd_parts) {
  const auto n = static_cast<std::ptrdiff_t>(links.size());
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const WallLink& l = links[static_cast<std::size_t>(k)];
    if (l.e == 0.0) continue;
    // f_i(x) = f*_i(x - c_i), f_-i(x) = f*_-i(x + c_i): the slots apply_wall_links reads from `previous`.
    const double odd = 0.5 * (f[layout.slot(l.dir, l.behind)] - f[layout.slot(D3Q19::opposite(l.dir), l.target)]);
    odd_parts[static_cast<std::size_t>(l.odd_slot)] = l.dir <= D3Q19::half ? odd : -odd;
  }
}

std::vector<AaWallLink> resolve_aa_links(std::span<const WallLink> links, const AaLayout& layout) {
  std::vector<AaWallLink> resolved;
  resolved.reserve(links.size());
  for (const WallLink& l : links) {
    const int o = D3Q19::opposite(l.dir);
    resolved.push_back(AaWallLink{.post_i = layout.slot(l.dir, l.node),
                                  .post_o = layout.slot(o, l.node),
                                  .second = layout.slot(l.dir, l.second),
                                  .target = layout.slot(o, l.target),
                                  .a = l.a, .b = l.b, .c = l.c, .d = l.d, .e = l.e,
                                  .odd_slot = l.odd_slot,
                                  .force_coef = l.force_coef,
                                  .odd_negated = l.dir > D3Q19::half});
  }
  return resolved;
}

void apply_wall_links_aa(std::span<const AaWallLink> links, double* f, std::span<const double> odd_parts,
                         const common::Vec3* body_force) {
  const auto n = static_cast<std::ptrdiff_t>(links.size());
  // As apply_wall_links: only tens of thousands of links are worth a parallel region.
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const AaWallLink& l = links[static_cast<std::size_t>(k)];
    const double post_i = f[l.post_i];
    const double post_o = f[l.post_o];
    double odd_pre = 0.0;
    if (l.e != 0.0) {
      const double pair = odd_parts[static_cast<std::size_t>(l.odd_slot)];
      odd_pre = l.odd_negated ? -pair : pair;
    }
    const double odd_change = odd_pre - 0.5 * (post_i - post_o);
    double value = l.a * post_i + l.b * f[l.second] + l.c * post_o + l.d + l.e * odd_change;
    if (body_force != nullptr) value += dot(l.force_coef, *body_force);
    f[l.target] = value;
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
