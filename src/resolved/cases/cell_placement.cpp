// SPDX-License-Identifier: MIT
// Seeded random sequential addition of randomly oriented cells at a target hematocrit.
#include "resolved/cases/cell_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <unordered_map>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

using common::Vec3;
using Rotation = std::array<Vec3, 3>;   // rows

/// Voxels across the rest mesh's largest extent of the inside/outside map: 0.16 um for a 7.8 um cell, well under the
/// default gap, so a vertex misjudged at the surface is still held off by the gap test.
constexpr int kInsideVoxels = 50;

Vec3 rotate(const Rotation& r, const Vec3& v) { return {common::dot(r[0], v), common::dot(r[1], v), common::dot(r[2], v)}; }
Vec3 rotate_back(const Rotation& r, const Vec3& v) { return v.x * r[0] + v.y * r[1] + v.z * r[2]; }

/// Uniform random rotation from a uniform unit quaternion (Shoemake 1992, Graphics Gems III).
Rotation random_rotation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double u1 = u(rng), u2 = 2.0 * std::numbers::pi * u(rng), u3 = 2.0 * std::numbers::pi * u(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
  return {Vec3{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          Vec3{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          Vec3{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

/// Which voxels of the rest mesh's box (centred on its centroid) lie inside it: crossings of vertical rays through
/// the voxel columns' centres with the triangles, inside between odd and even crossings.
class InsideMap {
 public:
  explicit InsideMap(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& triangles) {
    for (const auto& p : v) {
      for (int a = 0; a < 3; ++a) {
        lo_[a] = std::min(lo_[a], p[a]);
        hi_[a] = std::max(hi_[a], p[a]);
      }
    }
    h_ = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]}) / kInsideVoxels;
    for (int a = 0; a < 3; ++a) n_[a] = static_cast<int>(std::ceil((hi_[a] - lo_[a]) / h_)) + 1;
    inside_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2], 0);
    std::vector<double> z;
    for (int i = 0; i < n_[0]; ++i) {
      for (int j = 0; j < n_[1]; ++j) {
        const double x = lo_[0] + (i + 0.5) * h_, y = lo_[1] + (j + 0.5) * h_;
        z.clear();
        for (const auto& t : triangles) {
          const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
          const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
          if (det == 0.0) continue;
          const double s = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
          const double r = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
          if (s < 0.0 || r < 0.0 || s + r > 1.0) continue;
          z.push_back(a.z + s * (b.z - a.z) + r * (c.z - a.z));
        }
        std::sort(z.begin(), z.end());
        for (int k = 0; k < n_[2]; ++k) {
          const double zk = lo_[2] + (k + 0.5) * h_;
          const auto below = std::lower_bound(z.begin(), z.end(), zk) - z.begin();
          inside_[index(i, j, k)] = static_cast<char>(below % 2);
        }
      }
    }
  }
  /// p relative to the mesh's centroid, in its own (rest) frame.
  [[nodiscard]] bool inside(const Vec3& p) const {
    int ijk[3];
    for (int a = 0; a < 3; ++a) {
      const double f = (p[a] - lo_[a]) / h_;
      if (f < 0.0 || f >= n_[a]) return false;
      ijk[a] = static_cast<int>(f);
    }
    return inside_[index(ijk[0], ijk[1], ijk[2])] != 0;
  }
  [[nodiscard]] double bounding_radius(const std::vector<Vec3>& v) const {
    double r = 0.0;
    for (const auto& p : v) r = std::max(r, common::norm(p));
    return r;
  }

 private:
  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * n_[1] + j) * n_[2] + k;
  }
  std::array<double, 3> lo_{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::max()};
  std::array<double, 3> hi_{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                            std::numeric_limits<double>::lowest()};
  std::array<int, 3> n_{};
  double h_ = 0.0;
  std::vector<char> inside_;
};

Vec3 minimum_image(Vec3 d, const PlacementBox& box) {
  for (int a = 0; a < 3; ++a) {
    if (!box.periodic[a]) continue;
    const double l = box.upper_m[a] - box.lower_m[a];
    d[a] -= l * std::round(d[a] / l);
  }
  return d;
}

/// The placed cells' vertices in bins no smaller than the gap (periodic axes: a whole number of bins per period).
class VertexBins {
 public:
  VertexBins(const PlacementBox& box, double gap) : box_(box) {
    for (int a = 0; a < 3; ++a) {
      const double l = box.upper_m[a] - box.lower_m[a];
      count_[a] = box.periodic[a] ? std::max(1, static_cast<int>(std::floor(l / gap))) : 0;
      size_[a] = box.periodic[a] ? l / count_[a] : gap;
    }
  }
  void add(const Vec3& p) { bins_[key(bin_of(p))].push_back(p); }
  /// Whether any stored vertex lies within `gap` of p (minimum image).
  [[nodiscard]] bool any_within(const Vec3& p, double gap) const {
    const auto c = bin_of(p);
    std::vector<long long> keys;
    for (int i = -1; i <= 1; ++i) {
      for (int j = -1; j <= 1; ++j) {
        for (int k = -1; k <= 1; ++k) keys.push_back(key({c[0] + i, c[1] + j, c[2] + k}));
      }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (const long long k : keys) {
      const auto it = bins_.find(k);
      if (it == bins_.end()) continue;
      for (const Vec3& q : it->second) {
        if (common::norm(minimum_image(q - p, box_)) < gap) return true;
      }
    }
    return false;
  }

 private:
  [[nodiscard]] std::array<long long, 3> bin_of(const Vec3& p) const {
    std::array<long long, 3> b{};
    for (int a = 0; a < 3; ++a) b[a] = static_cast<long long>(std::floor((p[a] - box_.lower_m[a]) / size_[a]));
    return b;
  }
  [[nodiscard]] long long key(std::array<long long, 3> b) const {
    for (int a = 0; a < 3; ++a) {
      if (count_[a] > 0) b[a] = ((b[a] % count_[a]) + count_[a]) % count_[a];
    }
    constexpr long long kSpan = 1 << 20;   // bins per axis far beyond any box / gap
    return ((b[0] + kSpan / 2) * kSpan + (b[1] + kSpan / 2)) * kSpan + (b[2] + kSpan / 2);
  }
  PlacementBox box_;
  std::array<int, 3> count_{};
  std::array<double, 3> size_{};
  std::unordered_map<long long, std::vector<Vec3>> bins_;
};

struct Placed {
  Rotation rotation;
  Vec3 centre;
};

}  // namespace

Placement place_cells(const TriangleMesh& rest, const PlacementBox& box, const PlacementSpec& spec) {
  Placement out;
  out.cell_volume_m3 = mesh_volume_m3(rest);
  out.box_volume_m3 = 1.0;
  for (int a = 0; a < 3; ++a) out.box_volume_m3 *= box.upper_m[a] - box.lower_m[a];
  const long n = std::lround(spec.hematocrit * out.box_volume_m3 / out.cell_volume_m3);
  if (n < 1) {
    throw PlacementImpossible(fmt::format("hematocrit {:g} is under half a cell in the {:.4g} um^3 box (one cell of "
                                          "{:.4g} um^3 is {:.4g}); raise it or enlarge the box", spec.hematocrit,
                                          out.box_volume_m3 * 1e18, out.cell_volume_m3 * 1e18,
                                          out.cell_volume_m3 / out.box_volume_m3));
  }
  const Vec3 centroid = mesh_centroid_m(rest);
  std::vector<Vec3> body;
  for (const auto& v : rest.vertices_m) body.push_back(v - centroid);
  const InsideMap inside(body, rest.triangles);
  const double radius = inside.bounding_radius(body);
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  VertexBins bins(box, spec.min_gap_m);
  std::vector<Placed> placed;
  std::vector<Vec3> x(body.size());
  for (long c = 0; c < n; ++c) {
    bool ok = false;
    Placed accepted{};
    for (int attempt = 0; attempt < spec.attempts_per_cell && !ok; ++attempt) {
      ++out.attempts;
      const Rotation r = random_rotation(rng);
      Vec3 centre;
      for (int a = 0; a < 3; ++a) centre[a] = box.lower_m[a] + unit(rng) * (box.upper_m[a] - box.lower_m[a]);
      ok = true;
      for (std::size_t v = 0; v < body.size() && ok; ++v) {
        x[v] = centre + rotate(r, body[v]);
        for (int a = 0; a < 3 && ok; ++a) {
          if (box.periodic[a]) continue;
          ok = x[v][a] >= box.lower_m[a] + spec.wall_clearance_m && x[v][a] <= box.upper_m[a] - spec.wall_clearance_m;
        }
        ok = ok && !bins.any_within(x[v], spec.min_gap_m);
      }
      // No vertex of one cell inside the other, for the pairs whose bounding spheres meet.
      for (std::size_t p = 0; p < placed.size() && ok; ++p) {
        const Vec3 d = minimum_image(centre - placed[p].centre, box);
        if (common::norm(d) >= 2.0 * radius) continue;
        for (std::size_t v = 0; v < body.size() && ok; ++v) {
          // this cell's vertex in the other's frame, and the other's vertex in this cell's frame
          ok = !inside.inside(rotate_back(placed[p].rotation, d + rotate(r, body[v]))) &&
               !inside.inside(rotate_back(r, rotate(placed[p].rotation, body[v]) - d));
        }
      }
      if (ok) accepted = {r, centre};
    }
    if (!ok) {
      throw PlacementImpossible(fmt::format("placed {} of {} cells (hematocrit {:.4g} of the {:g} asked): cell {} found "
                                            "no place without overlap in {} random tries (gap {:g} m, wall clearance "
                                            "{:g} m); lower the hematocrit or enlarge the box", c, n,
                                            static_cast<double>(c) * out.cell_volume_m3 / out.box_volume_m3,
                                            spec.hematocrit, c + 1, spec.attempts_per_cell, spec.min_gap_m,
                                            spec.wall_clearance_m));
    }
    placed.push_back(accepted);
    out.cells_m.push_back(x);   // the accepted try's vertices
    for (const auto& p : x) bins.add(p);
  }
  out.hematocrit = static_cast<double>(n) * out.cell_volume_m3 / out.box_volume_m3;
  return out;
}

double min_intercell_distance_m(const std::vector<std::vector<common::Vec3>>& cells_m, const PlacementBox& box) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < cells_m.size(); ++a) {
    for (std::size_t b = a + 1; b < cells_m.size(); ++b) {
      for (const auto& p : cells_m[a]) {
        for (const auto& q : cells_m[b]) best = std::min(best, common::norm(minimum_image(q - p, box)));
      }
    }
  }
  return best;
}

}  // namespace hs::resolved
