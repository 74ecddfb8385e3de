// SPDX-License-Identifier: MIT
// The channel frame from the signed distance: wall normal, inscribed radius and the section's mean flow.
#include "unresolved/coupling/channel_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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
  const FvmGrid& grid = fluid.grid();
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
          const int n = grid.cells()[a];
          if (grid.periodic(static_cast<int>(a))) c[a] = ((c[a] % n) + n) % n;
          inside = inside && c[a] >= 0 && c[a] < n;
        }
        if (!inside || fraction(c[0], c[1], c[2]) <= 0.0) continue;
        Vec3 d;
        for (int a = 0; a < 3; ++a) d[a] = grid.origin_m()[a] + (unwrapped[static_cast<std::size_t>(a)] + 0.5) * dx - at.centre_m[a];
        const double along = dot(d, out.direction);
        if (std::abs(along) >= 1.5 * dx || norm(d - along * out.direction) > at.channel_radius_m + dx) continue;
        const double e = eps(c[0], c[1], c[2]);
        const Vec3 mixture = e * fluid.cell_velocity(c[0], c[1], c[2]) + (1.0 - e) * us(c[0], c[1], c[2]);
        flux += fraction(c[0], c[1], c[2]) * dot(mixture, out.direction);
        volume += fraction(c[0], c[1], c[2]);
      }
    }
  }
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
    const auto centre = grid.cell_of(points_[flat].centre_m);
    section_[flat] = centre ? grid.fluid_fractions().index((*centre)[0], (*centre)[1], (*centre)[2]) : flat;
    have_point_[flat] = 1;
    if (centre && section_[flat] != flat) (void)cell_point(*centre, section_[flat]);
  }
  return points_[flat];
}

ChannelFrame::Local ChannelFrame::at(const Vec3& x_m) {
  const FvmGrid& grid = fluid_.grid();
  const auto cell = grid.cell_of(x_m);
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
