// SPDX-License-Identifier: MIT
// Overlap tests of rigid, scaled copies of a rest mesh: walls, vertex gap (binned) and inside/outside (voxel map).
#include "resolved/cases/placement_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hs::resolved::placement {
namespace {

using common::Vec3;

/// Voxels across the rest mesh's largest extent of the inside/outside map: 0.16 um for a 7.8 um cell, well under the
/// default gap, so a vertex misjudged at the surface is still held off by the gap test.
constexpr int kInsideVoxels = 50;
/// Most bins of the vertex grid (~100 MB of empty vectors at most): a large box with a small gap gets larger bins.
constexpr double kMaxBins = 4.0e6;

Vec3 rotate(const Rotation& r, const Vec3& v) {
  return {common::dot(r[0], v), common::dot(r[1], v), common::dot(r[2], v)};
}
Vec3 rotate_back(const Rotation& r, const Vec3& v) { return v.x * r[0] + v.y * r[1] + v.z * r[2]; }

}  // namespace

Rotation rotation_of(const Quaternion& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {Vec3{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          Vec3{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          Vec3{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

Quaternion random_quaternion(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double u1 = u(rng), u2 = 2.0 * std::numbers::pi * u(rng), u3 = 2.0 * std::numbers::pi * u(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return {a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3)};
}

Quaternion turned(const Quaternion& q, const Vec3& axis, double angle) {
  const double c = std::cos(0.5 * angle), s = std::sin(0.5 * angle);
  const double w = c, x = s * axis.x, y = s * axis.y, z = s * axis.z;
  Quaternion r{w * q[0] - x * q[1] - y * q[2] - z * q[3], w * q[1] + x * q[0] + y * q[3] - z * q[2],
               w * q[2] - x * q[3] + y * q[0] + z * q[1], w * q[3] + x * q[2] - y * q[1] + z * q[0]};
  const double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (double& e : r) e /= n;
  return r;
}

// Crossings of vertical rays through the voxel columns' centres with the triangles: inside between odd and even ones.
InsideMap::InsideMap(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& triangles) {
  lo_.fill(std::numeric_limits<double>::max());
  hi_.fill(std::numeric_limits<double>::lowest());
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

bool InsideMap::inside(const Vec3& p) const {
  int ijk[3];
  for (int a = 0; a < 3; ++a) {
    const double f = (p[a] - lo_[a]) / h_;
    if (f < 0.0 || f >= n_[a]) return false;
    ijk[a] = static_cast<int>(f);
  }
  return inside_[index(ijk[0], ijk[1], ijk[2])] != 0;
}

std::size_t InsideMap::index(int i, int j, int k) const {
  return (static_cast<std::size_t>(i) * n_[1] + j) * n_[2] + k;
}

namespace {
std::vector<Vec3> body_of(const TriangleMesh& rest) {
  const Vec3 centroid = mesh_centroid_m(rest);
  std::vector<Vec3> body;
  for (const auto& v : rest.vertices_m) body.push_back(v - centroid);
  return body;
}
}  // namespace

CellGeometry::CellGeometry(const TriangleMesh& rest, const PlacementBox& box, double gap_m, double wall_clearance_m)
    : box_(box), gap_m_(gap_m), wall_clearance_m_(wall_clearance_m), body_(body_of(rest)),
      inside_(body_, rest.triangles), cell_volume_m3_(mesh_volume_m3(rest)) {
  for (const auto& p : body_) radius_m_ = std::max(radius_m_, common::norm(p));
}

bool CellGeometry::vertices_within_walls(const Pose& pose, double scale, std::vector<Vec3>& x) const {
  const Rotation r = rotation_of(pose.q);
  x.resize(body_.size());
  for (std::size_t v = 0; v < body_.size(); ++v) {
    x[v] = scale == 1.0 ? pose.centre + rotate(r, body_[v]) : pose.centre + scale * rotate(r, body_[v]);
    for (int a = 0; a < 3; ++a) {
      if (box_.periodic[a]) continue;
      if (x[v][a] < box_.lower_m[a] + wall_clearance_m_ || x[v][a] > box_.upper_m[a] - wall_clearance_m_) return false;
    }
  }
  return true;
}

bool CellGeometry::interpenetrate(const Pose& a, const Pose& b, double scale) const {
  const Vec3 d = minimum_image(a.centre - b.centre);   // a's centre seen from b's
  if (common::norm(d) >= 2.0 * scale * radius_m_) return false;
  const Rotation ra = rotation_of(a.q), rb = rotation_of(b.q);
  for (const Vec3& bv : body_) {
    // a's vertex in b's frame, and b's vertex in a's frame, both back at rest size
    if (inside_.inside(rotate_back(rb, d + scale * rotate(ra, bv)) / scale)) return true;
    if (inside_.inside(rotate_back(ra, scale * rotate(rb, bv) - d) / scale)) return true;
  }
  return false;
}

Vec3 CellGeometry::minimum_image(Vec3 d) const {
  for (int a = 0; a < 3; ++a) {
    if (!box_.periodic[a]) continue;
    const double l = box_.upper_m[a] - box_.lower_m[a];
    d[a] -= l * std::round(d[a] / l);
  }
  return d;
}

Vec3 CellGeometry::wrapped(Vec3 c) const {
  for (int a = 0; a < 3; ++a) {
    if (!box_.periodic[a]) continue;
    const double l = box_.upper_m[a] - box_.lower_m[a];
    c[a] -= l * std::floor((c[a] - box_.lower_m[a]) / l);
  }
  return c;
}

VertexBins::VertexBins(const PlacementBox& box, double gap_m) : box_(box), gap2_(gap_m * gap_m) {
  double size = gap_m;
  for (;;) {
    double total = 1.0;
    for (int a = 0; a < 3; ++a) {
      const double l = box.upper_m[a] - box.lower_m[a];
      count_[a] = std::max(1, static_cast<int>(std::floor(l / size)));
      size_[a] = l / count_[a];   // >= size: a vertex within the gap lies in a neighbouring bin
      total *= count_[a];
    }
    if (total <= kMaxBins) break;
    size *= 2.0;
  }
  bins_.resize(static_cast<std::size_t>(count_[0]) * count_[1] * count_[2]);
  listed_.assign(bins_.size(), 0);
}

int VertexBins::bin_along(int axis, double coordinate) const {
  const int i = static_cast<int>(std::floor((coordinate - box_.lower_m[axis]) / size_[axis]));
  if (box_.periodic[axis]) return ((i % count_[axis]) + count_[axis]) % count_[axis];
  return std::clamp(i, 0, count_[axis] - 1);   // a wall's bins also hold what lies beyond it
}

Vec3 VertexBins::wrapped(Vec3 p) const {
  for (int a = 0; a < 3; ++a) {
    if (!box_.periodic[a]) continue;
    const double l = box_.upper_m[a] - box_.lower_m[a];
    p[a] -= l * std::floor((p[a] - box_.lower_m[a]) / l);
    if (p[a] >= box_.upper_m[a]) p[a] = box_.lower_m[a];   // rounded up onto the face: the same point one period back
  }
  return p;
}

void VertexBins::add(int cell, const std::vector<Vec3>& x) {
  for (const Vec3& v : x) {
    const Vec3 p = wrapped(v);
    const std::size_t b = flat(bin_along(0, p.x), bin_along(1, p.y), bin_along(2, p.z));
    if (listed_[b] == 0) {
      listed_[b] = 1;
      filled_.push_back(b);
    }
    bins_[b].push_back({p, cell});
  }
}

void VertexBins::remove(int cell, const std::vector<Vec3>& x) {
  for (const Vec3& v : x) {
    const Vec3 p = wrapped(v);
    std::erase_if(bins_[flat(bin_along(0, p.x), bin_along(1, p.y), bin_along(2, p.z))],
                  [cell](const Entry& e) { return e.cell == cell; });
  }
}

void VertexBins::clear() {
  for (const std::size_t b : filled_) {
    bins_[b].clear();
    listed_[b] = 0;
  }
  filled_.clear();
}

bool VertexBins::any_within(const Vec3& v, int self) const {
  // The distinct bins next to p's along each axis, with the shift that brings a stored vertex next to p across a
  // periodic face (a period of fewer than three bins: the nearest image per vertex instead).
  const Vec3 p = wrapped(v);
  std::array<std::array<int, 3>, 3> near{};
  std::array<std::array<double, 3>, 3> shift{};
  std::array<int, 3> n{};
  std::array<bool, 3> nearest_image{};
  for (int a = 0; a < 3; ++a) {
    const int c = bin_along(a, p[a]);
    const double l = box_.upper_m[a] - box_.lower_m[a];
    nearest_image[a] = box_.periodic[a] && count_[a] < 3;
    for (int o = -1; o <= 1; ++o) {
      int i = c + o;
      double s = 0.0;
      if (box_.periodic[a]) {
        if (i < 0) {
          i += count_[a];
          s = -l;
        } else if (i >= count_[a]) {
          i -= count_[a];
          s = l;
        }
      } else if (i < 0 || i >= count_[a]) {
        continue;
      }
      if (std::find(near[a].begin(), near[a].begin() + n[a], i) != near[a].begin() + n[a]) continue;
      near[a][n[a]] = i;
      shift[a][n[a]++] = nearest_image[a] ? 0.0 : s;
    }
  }
  for (int i = 0; i < n[0]; ++i) {
    for (int j = 0; j < n[1]; ++j) {
      for (int k = 0; k < n[2]; ++k) {
        const Vec3 offset{shift[0][i] - p.x, shift[1][j] - p.y, shift[2][k] - p.z};
        for (const Entry& e : bins_[flat(near[0][i], near[1][j], near[2][k])]) {
          if (e.cell == self) continue;
          Vec3 d = e.p + offset;
          for (int a = 0; a < 3; ++a) {
            if (!nearest_image[a]) continue;
            const double l = box_.upper_m[a] - box_.lower_m[a];
            d[a] -= l * std::round(d[a] / l);
          }
          if (common::dot(d, d) < gap2_) return true;
        }
      }
    }
  }
  return false;
}

bool all_clear(const CellGeometry& g, const std::vector<Pose>& poses, double scale, VertexBins& bins) {
  std::vector<std::vector<Vec3>> x(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (!g.vertices_within_walls(poses[i], scale, x[i])) return false;
  }
  bins.clear();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    for (const Vec3& p : x[i]) {
      if (bins.any_within(p, static_cast<int>(i))) return false;   // against the cells before i
    }
    bins.add(static_cast<int>(i), x[i]);
  }
  for (std::size_t i = 0; i < poses.size(); ++i) {
    for (std::size_t j = i + 1; j < poses.size(); ++j) {
      if (g.interpenetrate(poses[i], poses[j], scale)) return false;
    }
  }
  return true;
}

std::vector<Pose> random_sequential_addition(const CellGeometry& g, long n, double scale, int attempts_per_cell,
                                             std::mt19937_64& rng, long& attempts) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const PlacementBox& box = g.box();
  VertexBins bins(box, g.gap_m());
  std::vector<Pose> placed;
  std::vector<Vec3> x;
  for (long c = 0; c < n; ++c) {
    bool ok = false;
    for (int attempt = 0; attempt < attempts_per_cell && !ok; ++attempt) {
      ++attempts;
      Pose pose{.q = random_quaternion(rng), .centre = {}};
      for (int a = 0; a < 3; ++a) pose.centre[a] = box.lower_m[a] + unit(rng) * (box.upper_m[a] - box.lower_m[a]);
      ok = g.vertices_within_walls(pose, scale, x);
      for (std::size_t v = 0; v < x.size() && ok; ++v) ok = !bins.any_within(x[v], -1);
      for (std::size_t p = 0; p < placed.size() && ok; ++p) ok = !g.interpenetrate(pose, placed[p], scale);
      if (ok) {
        placed.push_back(pose);
        bins.add(static_cast<int>(c), x);
      }
    }
    if (!ok) break;
  }
  return placed;
}

}  // namespace hs::resolved::placement
