// SPDX-License-Identifier: MIT
// Cartesian grid over a Shape: node classification, cut-face apertures, wall distances along links.
#include "unresolved/fvm/fvm_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

/// Sub-samples per face edge for cut-face apertures: 16^2 points put the open-area error of a face below
/// ~1/16 of a face for any wall orientation, and it averages out over the ~pi D / dx cut faces of a tube.
constexpr int kFaceSamples = 16;
/// Sub-samples per cell edge for the geometric fluid fraction (diagnostics and void-fraction clipping).
constexpr int kCellSamples = 6;
/// Smallest wall fraction along a link: closer walls are moved to 2% of a cell so the viscous
/// coefficient ~1/theta stays bounded (Gibou et al. 2002 treat theta < dx as on the node; 2% moves
/// the wall by at most 0.02 dx).
constexpr double kMinLinkFraction = 0.02;
/// Largest centroid-velocity factor of a cut face (only faces whose centre almost touches the wall
/// reach it; their flux is tiny either way).
constexpr double kMaxCentroidFactor = 4.0;

Vec3 unit(int a) {
  Vec3 e;
  e[a] = 1.0;
  return e;
}

}  // namespace

FvmGrid::FvmGrid(const hs::common::Shape& shape, const FvmGridSpec& spec,
                 const hs::common::CartesianDecomposition* slabs)
    : shape_(shape), spec_(spec), slabs_(slabs), dx_m_(spec.dx_m), lo_(spec.box_m.lo) {
  n_ = cells_of(spec);
  for (int a = 0; a < 3; ++a) {
    const bool lo_p = side(a, 0).type == SideType::periodic;
    const bool hi_p = side(a, 1).type == SideType::periodic;
    if (lo_p != hi_p) {
      throw hs::common::ConfigError(fmt::format("FVM grid: axis {} is periodic on one side only", "xyz"[a]));
    }
    periodic_[static_cast<std::size_t>(a)] = lo_p;
    for (int hi = 0; hi < 2; ++hi) {
      if (side(a, hi).type == SideType::velocity_inlet && !side(a, hi).inlet_velocity_m_s) {
        throw hs::common::ConfigError(fmt::format("FVM grid: inlet on axis {} has no velocity profile", "xyz"[a]));
      }
    }
  }
  global_n_ = n_;
  if (slabs_ != nullptr) {
    // A decomposition of another grid, or one split across x or y, is a caller's bug, not an input error.
    if (slabs_->global_nodes() != n_ || slabs_->ranks_per_axis()[0] != 1 || slabs_->ranks_per_axis()[1] != 1 ||
        slabs_->periodic()[2] != periodic_[2]) {
      throw std::invalid_argument("FvmGrid: the decomposition must split this grid's cells along z only");
    }
    n_[2] = slabs_->layout().n[2];
    first_plane_ = slabs_->offset()[2];
    lo_.z += first_plane_ * dx_m_;
  }
  set_up_openings();
  for (int c = 0; c < 3; ++c) {
    classify_nodes(c);
    compute_apertures(c);
  }
  if (!spec_.openings.empty()) finish_openings();
  compute_fluid_fractions();
}

int FvmGrid::node_count(int c, int a) const {
  const int n = n_[static_cast<std::size_t>(a)];
  if (c != a) return n;
  if (split_along(a)) return slabs_->on_global_face(a, 1) ? n + 1 : n;   // else face n is the next block's face 0
  return periodic(a) ? n : n + 1;
}

bool FvmGrid::in_range(int c, int a, int idx) const {
  if (split_along(a)) {   // a neighbouring block's node in the ghost layer counts, a node beyond a box face does not
    const int first = slabs_->on_global_face(a, 0) ? 0 : -1;
    const int end = slabs_->on_global_face(a, 1) ? node_count(c, a) : n_[static_cast<std::size_t>(a)] + 1;
    return idx >= first && idx < end;
  }
  return idx >= 0 && idx < node_count(c, a);
}

int FvmGrid::box_face(int c, int along) const {
  if (periodic(c)) return -1;
  const int n = n_[static_cast<std::size_t>(c)];
  if (split_along(c)) {
    if (along == 0 && slabs_->on_global_face(c, 0)) return 0;
    if (along == n && slabs_->on_global_face(c, 1)) return 1;
    return -1;
  }
  return along == 0 ? 0 : along == n ? 1 : -1;
}

std::array<int, 3> FvmGrid::cells_of(const FvmGridSpec& spec) {
  if (!(spec.dx_m > 0.0)) throw hs::common::ConfigError(fmt::format("FVM grid: dx_m = {} must be > 0", spec.dx_m));
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a) {
    const double extent = spec.box_m.hi[a] - spec.box_m.lo[a];
    const double cells = extent / spec.dx_m;
    const long count = std::lround(cells);
    if (count < 1 || std::abs(cells - static_cast<double>(count)) > 1e-6 * std::max(1.0, cells)) {
      throw hs::common::ConfigError(fmt::format(
          "FVM grid: the domain extent along axis {} ({} m) is not a whole number of cells of {} m ({:.6f} cells)",
          "xyz"[a], extent, spec.dx_m, cells));
    }
    n[static_cast<std::size_t>(a)] = static_cast<int>(count);
  }
  return n;
}

Vec3 FvmGrid::cell_centre_m(int i, int j, int k) const {
  // From the box's corner and the global index, so that a block computes every position of the whole grid's to
  // the bit (its geometry is then the whole grid's, sliced).
  const Vec3& o = spec_.box_m.lo;
  return {o.x + (i + 0.5) * dx_m_, o.y + (j + 0.5) * dx_m_, o.z + (k + first_plane_ + 0.5) * dx_m_};
}

Vec3 FvmGrid::node_position_m(int c, int i, int j, int k) const {
  Vec3 p = cell_centre_m(i, j, k);
  p[c] -= 0.5 * dx_m_;
  return p;
}

Vec3 FvmGrid::wrap(const Vec3& x_m) const {
  Vec3 x = x_m;
  for (int a = 0; a < 3; ++a) {
    if (!periodic(a)) continue;
    const double lo = spec_.box_m.lo[a];   // the whole box's period, also on a block
    const double length = global_n_[static_cast<std::size_t>(a)] * dx_m_;
    if (slabs_ != nullptr && a == 2) {
      // A block takes the image nearest to its middle (within half a period): a point just across the seam from the
      // bottom block is then read from that block's ghost planes, not from the top block's planes it does not hold.
      const double middle = lo + (first_plane_ + 0.5 * n_[2]) * dx_m_;
      const double periods = std::floor((x[a] - middle) / length + 0.5);
      if (periods != 0.0) x[a] -= periods * length;
      continue;
    }
    const double t = x[a] - lo;
    if (t >= 0.0 && t < length) continue;   // inside already (nearly always): no division, the point unchanged
    x[a] = lo + std::fmod(std::fmod(t, length) + length, length);
  }
  return x;
}

std::optional<std::array<int, 3>> FvmGrid::cell_of(const Vec3& x_m) const {
  const Vec3 x = wrap(x_m);
  std::array<int, 3> ijk{};
  for (int a = 0; a < 3; ++a) {
    const double s = (x[a] - lo_[a]) / dx_m_;
    const int n = n_[static_cast<std::size_t>(a)];
    if (!(s >= 0.0) || s > n) return std::nullopt;
    ijk[static_cast<std::size_t>(a)] = std::min(static_cast<int>(s), n - 1);
  }
  return ijk;
}

void FvmGrid::classify_nodes(int c) {
  auto& kind = kind_[static_cast<std::size_t>(c)];
  auto& fixed = fixed_[static_cast<std::size_t>(c)];
  kind = BlockField<std::uint8_t>(n_, static_cast<std::uint8_t>(NodeKind::solid));
  fixed = BlockField<double>(n_, 0.0);
  for (int k = 0; k < node_count(c, 2); ++k) {
    for (int j = 0; j < node_count(c, 1); ++j) {
      for (int i = 0; i < node_count(c, 0); ++i) {
        const Vec3 p = node_position_m(c, i, j, k);
        const bool fluid = shape_.signed_distance(p) < 0.0;
        if (!fluid) continue;
        NodeKind nk = NodeKind::active;
        const int along = std::array<int, 3>{i, j, k}[static_cast<std::size_t>(c)];
        if (const int face = box_face(c, along); face >= 0) {
          const SideCondition& s = side(c, face);
          if (!spec_.openings.empty() && classify_opening_node(c, {i, j, k}, p)) continue;
          if (s.type == SideType::wall) {
            nk = NodeKind::fixed;
            fixed(i, j, k) = s.wall_velocity_m_s[c];
          } else if (s.type == SideType::velocity_inlet) {
            nk = NodeKind::fixed;
            fixed(i, j, k) = s.inlet_velocity_m_s(p)[c];
          }
        }
        kind(i, j, k) = static_cast<std::uint8_t>(nk);
      }
    }
  }
  fill_ghosts(kind);
  fill_ghosts(fixed);
}

void FvmGrid::compute_apertures(int c) {
  auto& ap = aperture_[static_cast<std::size_t>(c)];
  auto& area = area_[static_cast<std::size_t>(c)];
  ap = BlockField<double>(n_, 0.0);
  area = BlockField<double>(n_, 0.0);
  const int t1 = (c + 1) % 3;
  const int t2 = (c + 2) % 3;
  const double h = dx_m_;
  for (int k = 0; k < node_count(c, 2); ++k) {
    for (int j = 0; j < node_count(c, 1); ++j) {
      for (int i = 0; i < node_count(c, 0); ++i) {
        if (kind(c, i, j, k) == NodeKind::solid) continue;
        const Vec3 p = node_position_m(c, i, j, k);
        const double d0 = -shape_.signed_distance(p);
        if (d0 > 0.75 * h) {   // farther than the face half-diagonal (0.707 h): the face is whole
          ap(i, j, k) = 1.0;
          area(i, j, k) = 1.0;
          continue;
        }
        int inside = 0;
        Vec3 centroid;
        for (int q = 0; q < kFaceSamples; ++q) {
          for (int r = 0; r < kFaceSamples; ++r) {
            const Vec3 s = p + ((q + 0.5) / kFaceSamples - 0.5) * h * unit(t1) + ((r + 0.5) / kFaceSamples - 0.5) * h * unit(t2);
            if (shape_.signed_distance(s) < 0.0) {
              ++inside;
              centroid += s;
            }
          }
        }
        const double a = std::max(1.0, static_cast<double>(inside)) / (kFaceSamples * kFaceSamples);
        const Vec3 cen = inside > 0 ? centroid / inside : p;
        // Flux through the open part = area x velocity at its centroid; the velocity grows linearly from
        // the wall, so u(centroid) = u(node) d(centroid) / d(node).
        const double factor = std::clamp(-shape_.signed_distance(cen) / d0, 0.0, kMaxCentroidFactor);
        area(i, j, k) = a;
        ap(i, j, k) = a * factor;
      }
    }
  }
  fill_ghosts(ap);
  fill_ghosts(area);
}

double FvmGrid::fluid_fraction_of_cell(int i, int j, int k_global) const {
  const double h = dx_m_;
  const Vec3& o = spec_.box_m.lo;   // the centre from the box corner and the global index, as cell_centre_m()
  const Vec3 p{o.x + (i + 0.5) * h, o.y + (j + 0.5) * h, o.z + (k_global + 0.5) * h};
  const double sd = shape_.signed_distance(p);
  if (std::abs(sd) > 0.87 * h) return sd < 0.0 ? 1.0 : 0.0;   // beyond the half-diagonal (0.866 h): one side
  int inside = 0;
  for (int q = 0; q < kCellSamples * kCellSamples * kCellSamples; ++q) {
    const Vec3 off{(q % kCellSamples + 0.5) / kCellSamples - 0.5, ((q / kCellSamples) % kCellSamples + 0.5) / kCellSamples - 0.5,
                   (q / (kCellSamples * kCellSamples) + 0.5) / kCellSamples - 0.5};
    if (shape_.signed_distance(p + h * off) < 0.0) ++inside;
  }
  return static_cast<double>(inside) / (kCellSamples * kCellSamples * kCellSamples);
}

void FvmGrid::compute_fluid_fractions() {
  fluid_fraction_ = BlockField<double>(n_, 0.0);
  for (int k = 0; k < n_[2]; ++k) {
    for (int j = 0; j < n_[1]; ++j) {
      for (int i = 0; i < n_[0]; ++i) fluid_fraction_(i, j, k) = fluid_fraction_of_cell(i, j, k + first_plane_);
    }
  }
  fill_ghosts(fluid_fraction_);
}

NodeLink FvmGrid::link(int c, std::array<int, 3> node, int dir) const {
  const int a = dir / 2;
  const int s = (dir % 2 == 1) ? 1 : -1;
  const Vec3 p = node_position_m(c, node[0], node[1], node[2]);
  const Vec3 pm = p + (s * dx_m_) * unit(a);
  std::array<int, 3> m = node;
  m[static_cast<std::size_t>(a)] += s;
  if (periodic(a) && !split_along(a)) {   // split: the neighbouring block's node is in the ghost layer
    const int count = node_count(c, a);
    m[static_cast<std::size_t>(a)] = (m[static_cast<std::size_t>(a)] % count + count) % count;
  }
  auto shape_fraction = [&](double limit) {
    if (shape_.signed_distance(pm) < 0.0) return limit;
    return std::min(limit, hs::common::wall_crossing_fraction(shape_, p, pm));
  };
  NodeLink l;
  if (!in_range(c, a, m[static_cast<std::size_t>(a)])) {
    const SideCondition& sc = side(a, s > 0 ? 1 : 0);
    Vec3 wall_point = p;
    wall_point[a] += 0.5 * s * dx_m_;
    // An opening holding the link's end on the face: a pressure outlet is open (zero gradient), an inlet or a
    // flow-fraction outlet holds a tangential velocity 0.
    const hs::common::OpeningCondition* open =
        spec_.openings.empty() ? nullptr : opening_at(a, s > 0 ? 1 : 0, wall_point);
    const bool open_outlet = open != nullptr && open->type == hs::common::OpeningFlowType::pressure_outlet;
    if (sc.type == SideType::pressure_outlet || a == c || open_outlet) {
      l.type = NodeLink::Type::neumann;   // zero gradient (an active node on the box is an outlet face)
      return l;
    }
    l.type = NodeLink::Type::dirichlet;
    l.value = open != nullptr                          ? 0.0
              : sc.type == SideType::velocity_inlet ? sc.inlet_velocity_m_s(wall_point)[c]
                                                      : sc.wall_velocity_m_s[c];
    l.theta = std::max(kMinLinkFraction, shape_fraction(0.5));
    return l;
  }
  const auto k = kind(c, m[0], m[1], m[2]);
  if (k == NodeKind::active) return l;
  l.type = NodeLink::Type::dirichlet;
  if (k == NodeKind::fixed) {
    l.value = fixed_values(c)(m[0], m[1], m[2]);
    l.theta = 1.0;
  } else {
    l.value = 0.0;
    l.theta = std::max(kMinLinkFraction, shape_fraction(1.0));
  }
  return l;
}

}  // namespace hs::unresolved
