// SPDX-License-Identifier: MIT
// Set-up of the fluid lattice: node classification, fluid runs, wall links and open-boundary nodes.
#include "resolved/lbm/fluid_lattice.hpp"

#include <algorithm>

namespace hs::resolved {

common::Vec3 FluidLattice::shape_point(const std::array<int, 3>& g) const {
  return placement_.origin + placement_.spacing * common::Vec3{static_cast<double>(g[0]), static_cast<double>(g[1]),
                                                               static_cast<double>(g[2])};
}

/// Fluid, solid (shape or face wall) or open-boundary ghost, from the global node index. Periodic axes wrap.
unsigned char FluidLattice::classify(const std::array<int, 3>& global) const {
  std::array<int, 3> g = global;
  int beyond_axis = -1;
  int beyond_side = 0;
  int beyond_count = 0;
  const auto& n = spec_.global_nodes;
  for (std::size_t a = 0; a < 3; ++a) {
    if (spec_.periodic[a]) {
      g[a] = ((g[a] % n[a]) + n[a]) % n[a];
    } else if (g[a] < 0 || g[a] >= n[a]) {
      beyond_axis = static_cast<int>(a);
      beyond_side = g[a] < 0 ? 0 : 1;
      ++beyond_count;
    }
  }
  const bool in_shape = shape_ == nullptr || shape_->signed_distance(shape_point(g)) < 0.0;
  if (beyond_count > 1) return kFaceSolid;
  if (beyond_count == 1) {
    const auto a = static_cast<std::size_t>(beyond_axis);
    if (!open_faces_[a][static_cast<std::size_t>(beyond_side)] || !in_shape) return kFaceSolid;
    std::array<int, 3> inner = g;
    inner[a] = beyond_side == 0 ? 0 : n[a] - 1;
    return classify(inner) == kFluid ? kOpen : kFaceSolid;
  }
  return in_shape ? kFluid : kShapeSolid;
}

void FluidLattice::classify_nodes() {
  flags_.assign(layout_.volume(), kFaceSolid);
  for (std::size_t n = 0; n < layout_.volume(); ++n) flags_[n] = classify(global_of(static_cast<std::ptrdiff_t>(n)));
}

void FluidLattice::build_runs() {
  runs_.clear();
  fluid_nodes_ = 0;
  for (int z = 0; z < layout_.n[2]; ++z) {
    for (int y = 0; y < layout_.n[1]; ++y) {
      int x = 0;
      while (x < layout_.n[0]) {
        while (x < layout_.n[0] && !is_fluid(x, y, z)) ++x;
        const int start = x;
        while (x < layout_.n[0] && is_fluid(x, y, z)) ++x;
        if (x > start) runs_.push_back({index(start, y, z), x - start});
        fluid_nodes_ += static_cast<std::size_t>(x - start);
      }
    }
  }
}

void FluidLattice::build_wall_links() {
  links_.clear();
  const auto& off = decomposition_->offset();
  for (int z = 0; z < layout_.n[2]; ++z) {
    for (int y = 0; y < layout_.n[1]; ++y) {
      for (int x = 0; x < layout_.n[0]; ++x) {
        if (!is_fluid(x, y, z)) continue;
        const std::ptrdiff_t node = index(x, y, z);
        const std::array<int, 3> g{x + off[0], y + off[1], z + off[2]};
        for (int i = 1; i < D3Q19::q; ++i) {
          const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
          const std::ptrdiff_t target = node + offsets_[static_cast<std::size_t>(i)];
          const unsigned char flag = flags_[static_cast<std::size_t>(target)];
          if (flag == kFluid || flag == kOpen) continue;
          const std::ptrdiff_t second = node - offsets_[static_cast<std::size_t>(i)];
          const unsigned char second_flag = flags_[static_cast<std::size_t>(second)];
          const bool second_usable = second_flag == kFluid || second_flag == kOpen;
          double q = 0.5;
          common::Vec3 u_wall;
          const bool bouzidi = flag == kShapeSolid && wall_rule_ == WallRule::bouzidi;
          // Half-way walls (q = 1/2) take the interpolated closure too when it differs from plain bounce-back: the
          // Lambda shift of the regularised collision (boundary_links.hpp).
          const bool shifted = spec_.collision.model == CollisionModel::regularized;
          const bool interpolated = bouzidi || shifted;
          if (bouzidi) {
            const common::Vec3 p = shape_point(g);
            const common::Vec3 step{static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
            q = common::wall_crossing_fraction(*shape_, p, p + placement_.spacing * step);
          } else if (flag == kFaceSolid) {
            for (std::size_t a = 0; a < 3; ++a) {
              const int ga = g[a] + c[a];
              if (!spec_.periodic[a] && (ga < 0 || ga >= spec_.global_nodes[a])) {
                u_wall = face_wall_velocity_[a][ga < 0 ? 0 : 1];
                break;
              }
            }
          }
          const double lambda_plus = 1.0 / spec_.collision.omega_plus() - 0.5;
          const double lambda_minus = 1.0 / spec_.collision.omega_minus() - 0.5;
          const double lambda = lambda_plus * lambda_minus;
          links_.push_back(make_wall_link(LinkSpec{.node = node, .target = target, .second = second,
                                                   .second_usable = second_usable, .dir = i, .q = q,
                                                   .interpolated = interpolated, .wall_velocity_lu = u_wall,
                                                   .rho_wall_lu = spec_.rho0_lu, .lambda_plus = lambda_plus,
                                                   .lambda = lambda,
                                                   .lambda_closure = shifted ? spec_.collision.closure_lambda() : lambda}));
        }
      }
    }
  }
}

/// AA: orders the links so that those at least two nodes from every block face come first (z-major, as built), and
/// indexes them and the runs by local z layer. Such a link reads and writes slots of nodes within one node of its
/// own, which no ghost pass touches (fill and fold work on the ghosts and the first and last interior layers). It
/// reads only what its node x and, with b != 0, x - c_i wrote in the step, and writes a slot no node reads in it:
/// it waits for layer z + 1 only when x - c_i lies there.
void FluidLattice::build_aa_layers() {
  build_odd_part_runs();
  const auto inner = [&](const WallLink& l) {
    const auto c = layout_.coords(l.node);
    for (std::size_t a = 0; a < 3; ++a) {
      if (c[a] < 2 || c[a] > layout_.n[a] - 3) return false;
    }
    return true;
  };
  const auto split = std::stable_partition(links_.begin(), links_.end(), inner);
  fused_links_ = static_cast<std::size_t>(split - links_.begin());
  const auto group = [&](const WallLink& l) {
    const bool with_above = l.b != 0.0 && D3Q19::c[static_cast<std::size_t>(l.dir)][2] == -1;
    return 2 * static_cast<std::size_t>(layout_.coords(l.node)[2]) + (with_above ? 1 : 0);
  };
  std::stable_sort(links_.begin(), split, [&](const WallLink& l, const WallLink& m) { return group(l) < group(m); });
  const auto nz = static_cast<std::size_t>(layout_.n[2]);
  layer_links_.assign(2 * nz + 1, 0);
  for (std::size_t k = 0; k < fused_links_; ++k) ++layer_links_[group(links_[k]) + 1];
  for (std::size_t g = 0; g < 2 * nz; ++g) layer_links_[g + 1] += layer_links_[g];
  index_layer_runs();
}

void FluidLattice::index_layer_runs() {
  const auto nz = static_cast<std::size_t>(layout_.n[2]);
  layer_runs_.assign(nz + 1, 0);
  for (const FluidRun& r : runs_) ++layer_runs_[static_cast<std::size_t>(layout_.coords(r.begin)[2]) + 1];
  for (std::size_t z = 0; z < nz; ++z) layer_runs_[z + 1] += layer_runs_[z];
}

/// AA: splits the runs so that the nodes with Bouzidi links (e != 0) form runs of their own, numbers those nodes in
/// run order for the kernel to keep their odd parts (FluidRun::odd_parts), and points each such link at its pair's
/// entry (WallLink::odd_slot). About one node in ten of the campaign tube has one; a separate pass that reread them
/// after the step cost 12 % of a cell run's time (bench resolved, session 7). These short runs at the rows' ends still
/// take ~16 % of the time for 10 % of the nodes: they open the rows' cache lines (a variant that kept the runs whole
/// and read the odd parts before each run paid the same there).
void FluidLattice::build_odd_part_runs() {
  odd_part_nodes_ = 0;
  std::vector<std::ptrdiff_t> entry(layout_.volume(), -1);
  for (const WallLink& l : links_) {
    if (l.e != 0.0) entry[static_cast<std::size_t>(l.node)] = 0;
  }
  std::vector<FluidRun> split;
  split.reserve(runs_.size());
  for (const FluidRun& run : runs_) {
    std::ptrdiff_t n = run.begin;
    const std::ptrdiff_t end = run.begin + run.length;
    while (n < end) {
      const bool keeps = entry[static_cast<std::size_t>(n)] >= 0;
      const std::ptrdiff_t start = n;
      while (n < end && (entry[static_cast<std::size_t>(n)] >= 0) == keeps) ++n;
      FluidRun part{.begin = start, .length = n - start, .odd_parts = -1};
      if (keeps) {
        part.odd_parts = static_cast<std::ptrdiff_t>(odd_part_nodes_);
        for (std::ptrdiff_t m = start; m < n; ++m) entry[static_cast<std::size_t>(m)] = static_cast<std::ptrdiff_t>(odd_part_nodes_++);
      }
      split.push_back(part);
    }
  }
  runs_ = std::move(split);
  const auto pairs = static_cast<std::ptrdiff_t>(odd_part_nodes_);
  for (WallLink& l : links_) {
    if (l.e == 0.0) continue;
    const int pair = l.dir <= D3Q19::half ? l.dir : D3Q19::opposite(l.dir);
    l.odd_slot = (pair - 1) * pairs + entry[static_cast<std::size_t>(l.node)];
  }
}

void FluidLattice::build_open_nodes() {
  open_nodes_.clear();
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t side = 0; side < 2; ++side) {
      const auto& face = open_faces_[a][side];
      if (!face || !decomposition_->on_global_face(static_cast<int>(a), static_cast<int>(side))) continue;
      const std::size_t b = (a + 1) % 3;
      const std::size_t c = (a + 2) % 3;
      for (int j = -1; j <= layout_.n[b]; ++j) {
        for (int k = -1; k <= layout_.n[c]; ++k) {
          std::array<int, 3> ghost{};
          ghost[a] = side == 0 ? -1 : layout_.n[a];
          ghost[b] = j;
          ghost[c] = k;
          const std::ptrdiff_t gi = index(ghost[0], ghost[1], ghost[2]);
          if (flags_[static_cast<std::size_t>(gi)] != kOpen) continue;
          std::array<int, 3> inner = ghost;
          inner[a] = side == 0 ? 0 : layout_.n[a] - 1;
          const auto g = global_of(gi);
          const common::Vec3 pos{static_cast<double>(g[0]), static_cast<double>(g[1]), static_cast<double>(g[2])};
          open_nodes_.push_back(OpenNode{.ghost = gi,
                                         .inner = index(inner[0], inner[1], inner[2]),
                                         .velocity_given = face->velocity_given,
                                         .u_lu = face->velocity_given ? face->profile(pos) : common::Vec3{},
                                         .rho_lu = face->rho_lu});
        }
      }
    }
  }
}

}  // namespace hs::resolved
