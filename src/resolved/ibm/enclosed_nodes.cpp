// SPDX-License-Identifier: MIT
// The lattice nodes a closed triangle mesh encloses, by signed ray crossings along z.
#include "resolved/ibm/enclosed_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hs::resolved {
namespace {

using common::Vec3;

struct Crossing {
  std::int64_t column;   // (j - j0) * columns along x + (i - i0)
  double z;
  int sign;              // orientation of the triangle's projection: +1 counter-clockwise seen from +z
};

/// Side of the point (x, y) against the directed line p -> q (sign of the edge function), with the point moved by
/// (e, e^2), e -> 0: on the line, the first non-zero term of the expansion decides, -(q.y - p.y) e, then (q.x - p.x) e^2.
/// Zero only for an edge whose end points project to one point (a triangle with such an edge covers no area).
int edge_side(const Vec3& p, const Vec3& q, double x, double y) {
  const double e = (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
  if (e != 0.0) return e > 0.0 ? 1 : -1;
  if (q.y != p.y) return q.y > p.y ? -1 : 1;
  if (q.x != p.x) return q.x > p.x ? 1 : -1;
  return 0;
}

/// edge_side of the triangle edge a -> b, always evaluated from the lower vertex index: both triangles sharing the
/// edge then see the same rounded value, negated, and never both (or neither) count a column through it.
int oriented_side(std::span<const Vec3> x, int a, int b, double px, double py) {
  const auto ua = static_cast<std::size_t>(a);
  const auto ub = static_cast<std::size_t>(b);
  return a < b ? edge_side(x[ua], x[ub], px, py) : -edge_side(x[ub], x[ua], px, py);
}

/// Twice the signed area of (p, q, point) in projection: the barycentric weight of the vertex opposite p -> q.
double edge_weight(const Vec3& p, const Vec3& q, double x, double y) {
  return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
}

/// Height of the triangle's plane over the column (x, y), kept within the triangle's z range (round-off).
double crossing_height(const Vec3& a, const Vec3& b, const Vec3& c, double x, double y) {
  const double wa = edge_weight(b, c, x, y);
  const double wb = edge_weight(c, a, x, y);
  const double wc = edge_weight(a, b, x, y);
  const double sum = wa + wb + wc;
  const double z = sum != 0.0 ? (wa * a.z + wb * b.z + wc * c.z) / sum : (a.z + b.z + c.z) / 3.0;
  return std::clamp(z, std::min({a.z, b.z, c.z}), std::max({a.z, b.z, c.z}));
}

/// The crossings of every triangle with the lattice columns its projection covers.
std::vector<Crossing> column_crossings(std::span<const Vec3> x, std::span<const std::array<int, 3>> triangles, int i0,
                                       int j0, std::int64_t columns_x) {
  std::vector<Crossing> out;
  out.reserve(4 * triangles.size());
  for (const auto& t : triangles) {
    const Vec3& a = x[static_cast<std::size_t>(t[0])];
    const Vec3& b = x[static_cast<std::size_t>(t[1])];
    const Vec3& c = x[static_cast<std::size_t>(t[2])];
    const int ilo = static_cast<int>(std::ceil(std::min({a.x, b.x, c.x})));
    const int ihi = static_cast<int>(std::floor(std::max({a.x, b.x, c.x})));
    const int jlo = static_cast<int>(std::ceil(std::min({a.y, b.y, c.y})));
    const int jhi = static_cast<int>(std::floor(std::max({a.y, b.y, c.y})));
    for (int j = jlo; j <= jhi; ++j) {
      for (int i = ilo; i <= ihi; ++i) {
        const double px = i;
        const double py = j;
        const int s = oriented_side(x, t[0], t[1], px, py);
        if (s == 0 || oriented_side(x, t[1], t[2], px, py) != s || oriented_side(x, t[2], t[0], px, py) != s) continue;
        out.push_back({.column = static_cast<std::int64_t>(j - j0) * columns_x + (i - i0),
                       .z = crossing_height(a, b, c, px, py),
                       .sign = s});
      }
    }
  }
  return out;
}

/// Node coordinate wrapped into the box along a periodic axis; false if beyond a non-periodic face.
bool wrap(int& c, int n, bool periodic) {
  if (periodic) {
    c = ((c % n) + n) % n;
    return true;
  }
  return c >= 0 && c < n;
}

}  // namespace

std::vector<std::array<int, 3>> enclosed_nodes(std::span<const Vec3> x_lu, std::span<const std::array<int, 3>> triangles,
                                               const NodeBox& box) {
  std::vector<std::array<int, 3>> inside;
  if (x_lu.empty() || triangles.empty()) return inside;
  Vec3 lo = x_lu[0];
  Vec3 hi = x_lu[0];
  for (const auto& p : x_lu) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  const int i0 = static_cast<int>(std::ceil(lo.x));
  const int j0 = static_cast<int>(std::ceil(lo.y));
  const std::int64_t columns_x = static_cast<std::int64_t>(std::floor(hi.x)) - i0 + 1;
  std::vector<Crossing> crossings = column_crossings(x_lu, triangles, i0, j0, std::max<std::int64_t>(columns_x, 1));
  // Per column, from the top down: the winding number below a crossing is the sum of the signs above it.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& p, const Crossing& q) {
    return p.column != q.column ? p.column < q.column : p.z > q.z;
  });
  for (std::size_t first = 0; first < crossings.size();) {
    std::size_t last = first;
    while (last < crossings.size() && crossings[last].column == crossings[first].column) ++last;
    int i = i0 + static_cast<int>(crossings[first].column % columns_x);
    int j = j0 + static_cast<int>(crossings[first].column / columns_x);
    const bool column_in_box = wrap(i, box.nodes[0], box.periodic[0]) && wrap(j, box.nodes[1], box.periodic[1]);
    int winding = 0;
    std::size_t next = first;
    const int k_top = static_cast<int>(std::floor(crossings[first].z));
    const int k_bottom = static_cast<int>(std::ceil(crossings[last - 1].z));
    for (int k = k_top; column_in_box && k >= k_bottom; --k) {
      while (next < last && crossings[next].z > k) winding += crossings[next++].sign;
      int kk = k;
      if (winding != 0 && wrap(kk, box.nodes[2], box.periodic[2])) inside.push_back({i, j, kk});
    }
    first = last;
  }
  return inside;
}

}  // namespace hs::resolved
