// SPDX-License-Identifier: MIT
// Random sequential addition with a linked-cell overlap test, and the FCC lattice fallback.
#include "unresolved/dem/insertion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/dem/cell_grid.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

// RSA attempts allowed per sphere before falling back to the lattice (RSA of spheres jams near phi ~ 0.38).
constexpr std::size_t rsa_attempts_per_sphere = 200;
// FCC nearest-neighbour distance = d (1 + gap): keeps lattice neighbours from touching by round-off.
constexpr double lattice_gap = 1e-9;

struct Region {
  const hs::common::Shape& shape;
  const Domain& domain;
  double r;
  Vec3 lo, hi;   // where centres may lie

  Region(const hs::common::Shape& s, const Domain& d, double radius) : shape(s), domain(d), r(radius) {
    const auto b = s.bounds();
    for (int a = 0; a < 3; ++a) {
      const double pad = d.periodic[a] ? 0.0 : radius;
      lo[a] = std::max(b.lo[a], d.box.lo[a] + pad);
      hi[a] = std::min(b.hi[a], d.box.hi[a] - pad);
      if (d.periodic[a]) { lo[a] = d.box.lo[a]; hi[a] = d.box.hi[a]; }
    }
  }
  [[nodiscard]] bool accessible(const Vec3& x) const {
    for (int a = 0; a < 3; ++a) {
      if (x[a] < lo[a] || x[a] > hi[a] || (domain.periodic[a] && x[a] >= hi[a])) return false;
    }
    return shape.signed_distance(x) <= -r;
  }
};

/// Linked cells of edge >= 2r over the domain box for the overlap test.
class OverlapGrid {
 public:
  OverlapGrid(const Domain& d, double r) : domain_(d), r_(r), grid_(d.box.lo, d.box.hi, 2.0 * r * (1.0 + 1e-12)) {
    head_.assign(static_cast<std::size_t>(grid_.n_cells()), -1);
  }
  [[nodiscard]] bool overlaps(const Vec3& x) const {
    std::array<std::vector<int>, 3> range;
    for (int a = 0; a < 3; ++a) {
      const int c = grid_.cell_coord(a, x[a]), n = grid_.n(a);
      if (domain_.periodic[a] && n < 3) {
        for (int k = 0; k < n; ++k) range[a].push_back(k);
      } else {
        for (int k = c - 1; k <= c + 1; ++k) {
          if (domain_.periodic[a]) range[a].push_back((k + n) % n);
          else if (k >= 0 && k < n) range[a].push_back(k);
        }
      }
    }
    for (int cz : range[2]) for (int cy : range[1]) for (int cx : range[0]) {
      for (int k = head_[static_cast<std::size_t>(grid_.index(cx, cy, cz))]; k >= 0; k = next_[static_cast<std::size_t>(k)]) {
        Vec3 dx = x - points_[static_cast<std::size_t>(k)];
        for (int a = 0; a < 3; ++a) {
          if (domain_.periodic[a]) dx[a] -= domain_.length_m(a) * std::round(dx[a] / domain_.length_m(a));
        }
        if (dot(dx, dx) < 4.0 * r_ * r_) return true;
      }
    }
    return false;
  }
  void add(const Vec3& x) {
    const auto c = static_cast<std::size_t>(grid_.index_of(x.x, x.y, x.z));
    next_.push_back(head_[c]);
    head_[c] = static_cast<int>(points_.size());
    points_.push_back(x);
  }
  [[nodiscard]] const std::vector<Vec3>& points() const { return points_; }

 private:
  const Domain& domain_;
  double r_;
  CellGrid grid_;
  std::vector<int> head_, next_;
  std::vector<Vec3> points_;
};

std::vector<Vec3> fcc_sites(const Region& region) {
  const double a0 = std::numbers::sqrt2 * 2.0 * region.r * (1.0 + lattice_gap);
  std::array<double, 3> a{};
  std::array<long, 3> n{};
  for (int k = 0; k < 3; ++k) {
    const double extent = region.hi[k] - region.lo[k];
    if (region.domain.periodic[k]) {
      n[k] = std::max(1L, static_cast<long>(std::floor(extent / a0)));
      a[k] = extent / static_cast<double>(n[k]);
    } else {
      a[k] = a0;
      n[k] = static_cast<long>(std::floor(extent / a0)) + 1;
    }
  }
  static constexpr double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<Vec3> sites;
  for (long iz = 0; iz < n[2]; ++iz) for (long iy = 0; iy < n[1]; ++iy) for (long ix = 0; ix < n[0]; ++ix) {
    for (const auto& b : basis) {
      const Vec3 x{region.lo.x + (static_cast<double>(ix) + b[0]) * a[0], region.lo.y + (static_cast<double>(iy) + b[1]) * a[1],
                   region.lo.z + (static_cast<double>(iz) + b[2]) * a[2]};
      if (region.accessible(x)) sites.push_back(x);
    }
  }
  return sites;
}

}  // namespace

double region_volume_m3(const hs::common::Shape& shape, const Domain& domain) {
  const auto b = shape.bounds();
  auto inside_box = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a) if (p[a] < domain.box.lo[a] - 1e-15 || p[a] > domain.box.hi[a] + 1e-15) return false;
    return true;
  };
  if (const auto* tube = dynamic_cast<const hs::common::Tube*>(&shape); tube != nullptr && inside_box(b.lo) && inside_box(b.hi)) {
    const auto& s = tube->spec();
    return std::numbers::pi * s.radius_m * s.radius_m * norm(s.end_m - s.start_m);
  }
  Vec3 lo, hi;
  for (int a = 0; a < 3; ++a) { lo[a] = std::max(b.lo[a], domain.box.lo[a]); hi[a] = std::min(b.hi[a], domain.box.hi[a]); }
  const double vol_box = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  if (!(vol_box > 0.0)) return 0.0;
  const double h = std::cbrt(vol_box / 2.0e6);
  std::array<long, 3> n{};
  for (int a = 0; a < 3; ++a) n[a] = std::max(1L, std::lround((hi[a] - lo[a]) / h));
  long inside = 0;
  for (long k = 0; k < n[2]; ++k) for (long j = 0; j < n[1]; ++j) for (long i = 0; i < n[0]; ++i) {
    const Vec3 p{lo.x + (static_cast<double>(i) + 0.5) * (hi.x - lo.x) / static_cast<double>(n[0]),
                 lo.y + (static_cast<double>(j) + 0.5) * (hi.y - lo.y) / static_cast<double>(n[1]),
                 lo.z + (static_cast<double>(k) + 0.5) * (hi.z - lo.z) / static_cast<double>(n[2])};
    if (shape.inside(p)) ++inside;
  }
  return vol_box * static_cast<double>(inside) / static_cast<double>(n[0] * n[1] * n[2]);
}

InsertionResult insert_at_volume_fraction(const hs::common::Shape& shape, const Domain& domain, const InsertionSpec& spec) {
  if (!(spec.volume_fraction >= 0.0 && spec.volume_fraction < 1.0) || !(spec.radius_m > 0.0)) {
    throw hs::common::ConfigError(fmt::format("{} = {} must be in [0, 1)", spec.key, spec.volume_fraction));
  }
  InsertionResult result;
  result.region_volume_m3 = region_volume_m3(shape, domain);
  const double v_sphere = 4.0 / 3.0 * std::numbers::pi * spec.radius_m * spec.radius_m * spec.radius_m;
  const auto n_target = static_cast<std::size_t>(std::llround(spec.volume_fraction * result.region_volume_m3 / v_sphere));
  const Region region(shape, domain, spec.radius_m);
  std::vector<Vec3> sites = fcc_sites(region);
  if (n_target > sites.size()) {
    throw hs::common::ConfigError(fmt::format(
        "{} = {} cannot be reached without overlaps: {} spheres of diameter {:.4g} m are needed in {:.4g} m^3, but at most "
        "{} fit (FCC lattice), i.e. {} <= {:.4f} here", spec.key, spec.volume_fraction, n_target, 2.0 * spec.radius_m,
        result.region_volume_m3, sites.size(), spec.key, static_cast<double>(sites.size()) * v_sphere / result.region_volume_m3));
  }
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  OverlapGrid grid(domain, spec.radius_m);
  const std::size_t max_attempts = rsa_attempts_per_sphere * n_target + 1000;
  for (std::size_t attempt = 0; attempt < max_attempts && grid.points().size() < n_target; ++attempt) {
    Vec3 x;
    for (int a = 0; a < 3; ++a) x[a] = region.lo[a] + u01(rng) * (region.hi[a] - region.lo[a]);
    if (region.accessible(x) && !grid.overlaps(x)) grid.add(x);
  }
  if (grid.points().size() == n_target) {
    result.positions_m = grid.points();
  } else {
    std::shuffle(sites.begin(), sites.end(), rng);
    sites.resize(n_target);
    result.positions_m = std::move(sites);
    result.used_lattice = true;
  }
  result.achieved_fraction = static_cast<double>(n_target) * v_sphere / std::max(result.region_volume_m3, 1e-300);
  return result;
}

}  // namespace hs::unresolved
