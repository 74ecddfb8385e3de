// SPDX-License-Identifier: MIT
// The channel frame from the signed distance: wall normal, inscribed radius and the section's mean flow.
#include "unresolved/coupling/channel_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>
#include <stdexcept>

#include <mpi.h>

namespace hs::unresolved {
namespace {

using hs::common::Shape;
using hs::common::Vec3;

/// Gradient of the signed distance by central differences. The step is small enough that its truncation error in a
/// tube, (h / r)^2, stays below 1e-10 one cell from the axis, and large enough that round-off (1e-16 |sd| / h) does too.
Vec3 distance_gradient(const Shape& shape, const Vec3& x, double h) {
  Vec3 g;
  for (int a = 0; a < 3; ++a) {
    Vec3 d;
    d[a] = h;
    g[a] = (shape.signed_distance(x + d) - shape.signed_distance(x - d)) / (2.0 * h);
  }
  return g;
}

/// Maximises f on [lo, hi] by golden section (f unimodal there) to an interval of `tolerance`; returns the argmax.
template <class F>
double golden_maximum(F f, double lo, double hi, double tolerance) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = hi - ratio * (hi - lo);
  double b = lo + ratio * (hi - lo);
  double fa = f(a);
  double fb = f(b);
  while (hi - lo > tolerance) {
    if (fa < fb) {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = f(b);
    } else {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = f(a);
    }
  }
  return 0.5 * (lo + hi);
}

/// The whole grid's cell (i, j, k + first_plane) holding x (periodic axes wrapped), or nullopt outside the grid.
std::optional<std::array<int, 3>> global_cell_of(const FvmGrid& g, const Vec3& x) {
  std::array<int, 3> ijk{};
  for (int a = 0; a < 3; ++a) {
    const int n = g.global_cells()[static_cast<std::size_t>(a)];
    const double lo = g.origin_m()[a] - (a == 2 ? g.first_plane() * g.dx_m() : 0.0);
    double s = (x[a] - lo) / g.dx_m();
    if (g.periodic(a)) s -= n * std::floor(s / n);
    if (!(s >= 0.0) || s > n) return std::nullopt;
    ijk[static_cast<std::size_t>(a)] = std::min(static_cast<int>(s), n - 1);
  }
  return ijk;
}

std::int64_t global_key(const FvmGrid& g, const std::array<int, 3>& c) {
  const auto& n = g.global_cells();
  return (static_cast<std::int64_t>(c[2]) * n[1] + c[1]) * n[0] + c[0];
}

std::array<int, 3> global_cell_of_key(const FvmGrid& g, std::int64_t key) {
  const auto& n = g.global_cells();
  return {static_cast<int>(key % n[0]), static_cast<int>((key / n[0]) % n[1]), static_cast<int>(key / (static_cast<std::int64_t>(n[0]) * n[1]))};
}

/// The section's flux, sum of a (eps u + (1 - eps) Us) . t, and fluid volume, sum of a, over the cells whose centre
/// lies in its slab (channel_flow), a the cell's fluid fraction. On z-slabs only this block's own planes (a plane
/// beyond them is another rank's to count), whichever of the whole grid's planes the section reaches.
std::pair<double, double> section_sums(const FvmSolver& fluid, const ChannelPoint& at, const Vec3& direction) {
  const FvmGrid& grid = fluid.grid();
  const bool slabs = grid.slabs() != nullptr;
  const double dx = grid.dx_m();
  const double reach = at.channel_radius_m + 2.0 * dx;
  std::array<int, 3> lo{};
  std::array<int, 3> hi{};
  for (int a = 0; a < 3; ++a) {
    lo[static_cast<std::size_t>(a)] = static_cast<int>(std::floor((at.centre_m[a] - reach - grid.origin_m()[a]) / dx));
    hi[static_cast<std::size_t>(a)] = static_cast<int>(std::ceil((at.centre_m[a] + reach - grid.origin_m()[a]) / dx));
  }
  const BlockField<double>& fraction = grid.fluid_fractions();
  const BlockField<double>& eps = fluid.void_fraction();
  const BlockField<Vec3>& us = fluid.particle_velocity_m_s();
  double flux = 0.0;
  double volume = 0.0;
  for (int k = lo[2]; k <= hi[2]; ++k) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::array<int, 3> unwrapped{i, j, k};
        std::array<int, 3> c = unwrapped;
        bool inside = true;
        for (std::size_t a = 0; a < 3; ++a) {
          int n = grid.cells()[a];
          if (slabs && a == 2) {   // through the whole grid's index, back to this block's
            n = grid.global_cells()[2];
            c[2] += grid.first_plane();
            if (grid.periodic(2)) c[2] = ((c[2] % n) + n) % n;
            c[2] -= grid.first_plane();
            inside = inside && c[2] >= 0 && c[2] < grid.cells()[2];
            continue;
          }
          if (grid.periodic(static_cast<int>(a))) c[a] = ((c[a] % n) + n) % n;
          inside = inside && c[a] >= 0 && c[a] < n;
        }
        if (!inside || fraction(c[0], c[1], c[2]) <= 0.0) continue;
        Vec3 d;
        for (int a = 0; a < 3; ++a) d[a] = grid.origin_m()[a] + (unwrapped[static_cast<std::size_t>(a)] + 0.5) * dx - at.centre_m[a];
        const double along = dot(d, direction);
        if (std::abs(along) >= 1.5 * dx || norm(d - along * direction) > at.channel_radius_m + dx) continue;
        const double e = eps(c[0], c[1], c[2]);
        const Vec3 mixture = e * fluid.cell_velocity(c[0], c[1], c[2]) + (1.0 - e) * us(c[0], c[1], c[2]);
        flux += fraction(c[0], c[1], c[2]) * dot(mixture, direction);
        volume += fraction(c[0], c[1], c[2]);
      }
    }
  }
  return {flux, volume};
}

constexpr double kGradientStep = 1e-5;   // of the length scale
// A gradient this short means x sits on the medial axis (within half a step), where no wall is nearest.
constexpr double kMedialGradient = 0.5;

}  // namespace

ChannelPoint channel_point(const Shape& shape, const Vec3& x_m, double length_scale_m) {
  ChannelPoint p;
  p.wall_distance_m = -shape.signed_distance(x_m);
  const Vec3 g = distance_gradient(shape, x_m, kGradientStep * length_scale_m);
  const double gn = norm(g);
  if (!(gn >= kMedialGradient)) {
    p.channel_radius_m = p.wall_distance_m;
    p.centre_m = x_m;
    return p;
  }
  p.wall_normal = g / gn;
  // Along the line into the channel the wall distance rises until the medial axis and falls beyond it.
  auto depth = [&](double t) { return -shape.signed_distance(x_m - t * p.wall_normal); };
  const hs::common::Box3 box = shape.bounds();
  const double reach = norm(box.hi - box.lo);
  const double dt = 0.25 * length_scale_m;
  double t = 0.0;
  double f = p.wall_distance_m;
  while (t < reach) {
    const double next = depth(t + dt);
    if (!(next > f)) break;
    t += dt;
    f = next;
  }
  const double best = golden_maximum(depth, std::max(0.0, t - dt), t + dt, 1e-9 * length_scale_m);
  p.centre_m = x_m - best * p.wall_normal;
  p.channel_radius_m = std::max(f, depth(best));
  return p;
}

ChannelFlow channel_flow(const FvmSolver& fluid, const ChannelPoint& at) {
  ChannelFlow out;
  const Vec3 u_centre = fluid.velocity_at(at.centre_m);
  const double speed = norm(u_centre);
  if (!(speed > 0.0) || !(at.channel_radius_m > 0.0)) return out;
  out.direction = u_centre / speed;
  // The mixture's volume flux density eps u + (1 - eps) Us, averaged over the fluid volume of the cells whose centre
  // lies in the section's slab: within 1.5 dx of the centre along the flow (three cell layers in a grid-aligned
  // tube) and within R_c + dx of the medial axis (every cut cell of a tube's wall). In a developed flow the
  // average of the flux density over a slab is the section's flux over its area: Q / A in a tube.
  const auto [flux, volume] = section_sums(fluid, at, out.direction);
  out.mean_velocity_m_s = volume > 0.0 ? flux / volume : 0.0;
  return out;
}

ChannelFrame::ChannelFrame(const FvmSolver& fluid)
    : fluid_(fluid),
      points_(fluid.grid().fluid_fractions().data().size()),
      have_point_(points_.size(), 0),
      section_(points_.size(), 0),
      flows_(points_.size()),
      flow_step_(points_.size(), -1) {}

Vec3 ChannelFrame::wall_normal(const Vec3& x_m) const {
  const double h = kGradientStep * fluid_.grid().dx_m();
  const Vec3 g = distance_gradient(fluid_.grid().shape(), x_m, h);
  const double gn = norm(g);
  return gn >= kMedialGradient ? g / gn : Vec3{};
}

const ChannelPoint& ChannelFrame::cell_point(const std::array<int, 3>& cell, std::size_t flat) {
  if (have_point_[flat] == 0) {
    const FvmGrid& grid = fluid_.grid();
    points_[flat] = channel_point(grid.shape(), grid.cell_centre_m(cell[0], cell[1], cell[2]), grid.dx_m());
    have_point_[flat] = 1;
    if (grid.slabs() != nullptr) return points_[flat];   // the section: section_key()
    const auto centre = grid.cell_of(points_[flat].centre_m);
    section_[flat] = centre ? grid.fluid_fractions().index((*centre)[0], (*centre)[1], (*centre)[2]) : flat;
    if (centre && section_[flat] != flat) (void)cell_point(*centre, section_[flat]);
  }
  return points_[flat];
}

ChannelFrame::Local ChannelFrame::at(const Vec3& x_m) {
  const FvmGrid& grid = fluid_.grid();
  const auto cell = grid.cell_of(x_m);
  if (grid.slabs() != nullptr) {   // the flows prepare_sections() summed over the ranks
    if (!cell) throw std::logic_error("channel frame: a sphere sampled outside its rank's block");
    const std::size_t c = grid.fluid_fractions().index((*cell)[0], (*cell)[1], (*cell)[2]);
    const double radius = cell_point(*cell, c).channel_radius_m;
    const auto flow = slab_flows_.find(section_key(*cell, c));
    if (flow == slab_flows_.end()) throw std::logic_error("channel frame: prepare_sections() did not hold this section");
    return {radius, flow->second};
  }
  if (!cell) {   // outside the box (a sphere leaving through an opening): no memo
    const ChannelPoint p = channel_point(grid.shape(), x_m, grid.dx_m());
    return {p.channel_radius_m, channel_flow(fluid_, p)};
  }
  const std::size_t c = grid.fluid_fractions().index((*cell)[0], (*cell)[1], (*cell)[2]);
  const double radius = cell_point(*cell, c).channel_radius_m;
  // The section's flow is kept per cell holding a section centre, from that cell's own channel point: every cell
  // whose medial centre falls there (in a tube: one layer of cells) shares it, whichever asks first.
  const std::size_t s = section_[c];
  if (flow_step_[s] != step_) {
    flows_[s] = channel_flow(fluid_, points_[s]);
    flow_step_[s] = step_;
  }
  return {radius, flows_[s]};
}

}  // namespace hs::unresolved

namespace hs::unresolved {

std::int64_t ChannelFrame::section_key(const std::array<int, 3>& cell, std::size_t flat) {
  const FvmGrid& grid = fluid_.grid();
  if (section_key_.empty()) section_key_.assign(points_.size(), -1);
  if (section_key_[flat] < 0) {
    // As one rank keys it: the cell holding the medial centre of this cell's channel point, else the cell itself.
    const auto centre = global_cell_of(grid, cell_point(cell, flat).centre_m);
    const std::array<int, 3> own{cell[0], cell[1], cell[2] + grid.first_plane()};
    section_key_[flat] = global_key(grid, centre ? *centre : own);
  }
  return section_key_[flat];
}

void ChannelFrame::prepare_sections(const std::vector<Vec3>& xs) {
  const FvmGrid& grid = fluid_.grid();
  const MPI_Comm comm = grid.slabs()->comm();
  std::vector<std::int64_t> mine;
  for (const Vec3& x : xs) {
    const auto cell = grid.cell_of(x);
    if (!cell) throw std::logic_error("channel frame: a sphere sampled outside its rank's block");
    mine.push_back(section_key(*cell, grid.fluid_fractions().index((*cell)[0], (*cell)[1], (*cell)[2])));
  }
  std::sort(mine.begin(), mine.end());
  mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
  int ranks = 0;
  MPI_Comm_size(comm, &ranks);
  std::vector<int> counts(static_cast<std::size_t>(ranks));
  const int count = static_cast<int>(mine.size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::vector<int> displs(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<std::int64_t> keys(static_cast<std::size_t>(displs.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, MPI_INT64_T, keys.data(), counts.data(), displs.data(), MPI_INT64_T, comm);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // Each section's direction: the fluid velocity at its centre, from the rank whose block holds the centre (the
  // first and last blocks also take the centres beyond the grid's ends, as one rank's clamped interpolation does).
  const double dx = grid.dx_m();
  const int n_z = grid.cells()[2];
  const bool first = grid.first_plane() == 0;
  const bool last = grid.first_plane() + n_z == grid.global_cells()[2];
  const double z_lo = grid.origin_m().z;
  const double z_hi = z_lo + n_z * dx;
  const double length = grid.global_cells()[2] * dx;
  const double global_lo = z_lo - grid.first_plane() * dx;
  std::vector<double> sums(3 * keys.size(), 0.0);   // per section: the velocity at its centre
  for (std::size_t q = 0; q < keys.size(); ++q) {
    auto point = key_points_.find(keys[q]);
    if (point == key_points_.end()) {
      const std::array<int, 3> g = global_cell_of_key(grid, keys[q]);
      Vec3 centre = grid.cell_centre_m(g[0], g[1], g[2] - grid.first_plane());
      point = key_points_.emplace(keys[q], channel_point(grid.shape(), centre, dx)).first;
    }
    double z = point->second.centre_m.z;
    if (grid.periodic(2)) z -= length * std::floor((z - global_lo) / length);
    if ((z >= z_lo || first) && (z < z_hi || last)) {
      const Vec3 u = fluid_.velocity_at(point->second.centre_m);
      for (int a = 0; a < 3; ++a) sums[3 * q + static_cast<std::size_t>(a)] = u[a];
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, comm);
  // Each section's flux and volume over this block's own cells (channel_flow's slab and weights), then summed.
  std::vector<double> parts(2 * keys.size(), 0.0);
  for (std::size_t q = 0; q < keys.size(); ++q) {
    const ChannelPoint& at = key_points_.at(keys[q]);
    const Vec3 u{sums[3 * q], sums[3 * q + 1], sums[3 * q + 2]};
    const double speed = norm(u);
    if (!(speed > 0.0) || !(at.channel_radius_m > 0.0)) continue;
    std::tie(parts[2 * q], parts[2 * q + 1]) = section_sums(fluid_, at, u / speed);
  }
  MPI_Allreduce(MPI_IN_PLACE, parts.data(), static_cast<int>(parts.size()), MPI_DOUBLE, MPI_SUM, comm);
  slab_flows_.clear();
  for (std::size_t q = 0; q < keys.size(); ++q) {
    const Vec3 u{sums[3 * q], sums[3 * q + 1], sums[3 * q + 2]};
    ChannelFlow flow;
    const double speed = norm(u);
    if (speed > 0.0 && key_points_.at(keys[q]).channel_radius_m > 0.0) {
      flow.direction = u / speed;
      flow.mean_velocity_m_s = parts[2 * q + 1] > 0.0 ? parts[2 * q] / parts[2 * q + 1] : 0.0;
    }
    slab_flows_[keys[q]] = flow;
  }
}

}  // namespace hs::unresolved
