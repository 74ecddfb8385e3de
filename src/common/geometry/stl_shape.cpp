// SPDX-License-Identifier: MIT
// The fluid region enclosed by a closed triangle surface.
#include "common/geometry/stl_shape.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace hs::common {
namespace {

enum class Feature { face, vertex0, vertex1, vertex2, edge01, edge12, edge20 };

/// Closest point on triangle abc to p, and which feature it lies on (Ericson, Real-Time Collision
/// Detection, section 5.1.5, restated).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Feature& feature) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) { feature = Feature::vertex0; return a; }
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) { feature = Feature::vertex1; return b; }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) { feature = Feature::edge01; return a + (d1 / (d1 - d3)) * ab; }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) { feature = Feature::vertex2; return c; }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) { feature = Feature::edge20; return a + (d2 / (d2 - d6)) * ac; }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    feature = Feature::edge12;
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  feature = Feature::face;
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

double box_distance2(const Box3& b, const Vec3& p) {
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double e = std::max({b.lo[i] - p[i], 0.0, p[i] - b.hi[i]});
    d2 += e * e;
  }
  return d2;
}

}  // namespace

std::shared_ptr<StlShape> StlShape::load(const std::filesystem::path& file, double scale_to_m) {
  return std::make_shared<StlShape>(read_stl(file, scale_to_m), file.string());
}

StlShape::StlShape(TriangleMesh mesh, const std::string& source) : mesh_(std::move(mesh)) {
  require_closed_manifold(mesh_, source);
  const std::size_t nt = mesh_.triangles.size();
  face_normals_.resize(nt);
  vertex_normals_.assign(mesh_.vertices.size(), Vec3{});
  std::map<std::pair<int, int>, Vec3> edge_sum;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = mesh_.triangles[t];
    face_normals_[t] = normalized(cross(mesh_.vertices[tri[1]] - mesh_.vertices[tri[0]], mesh_.vertices[tri[2]] - mesh_.vertices[tri[0]]));
    for (int k = 0; k < 3; ++k) {
      const Vec3& v = mesh_.vertices[tri[k]];
      const Vec3 e1 = normalized(mesh_.vertices[tri[(k + 1) % 3]] - v);
      const Vec3 e2 = normalized(mesh_.vertices[tri[(k + 2) % 3]] - v);
      vertex_normals_[tri[k]] += std::acos(std::clamp(dot(e1, e2), -1.0, 1.0)) * face_normals_[t];
      const auto key = std::minmax(tri[k], tri[(k + 1) % 3]);
      edge_sum[{key.first, key.second}] += face_normals_[t];
    }
  }
  edge_normals_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = mesh_.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(tri[k], tri[(k + 1) % 3]);
      edge_normals_[t][static_cast<std::size_t>(k)] = edge_sum[{key.first, key.second}];
    }
  }
  order_.resize(nt);
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(2 * nt);
  build(0, static_cast<int>(nt));
}

int StlShape::build(int begin, int end) {
  Box3 box{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for (int i = begin; i < end; ++i) {
    for (int v : mesh_.triangles[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])]) {
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], mesh_.vertices[v][k]);
        box.hi[k] = std::max(box.hi[k], mesh_.vertices[v][k]);
      }
    }
  }
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({box, begin, end - begin, -1, -1});
  if (end - begin <= 4) return id;
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (box.hi[k] - box.lo[k] > box.hi[axis] - box.lo[axis]) axis = k;
  }
  const int mid = (begin + end) / 2;
  auto centroid = [&](int t) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
    return mesh_.vertices[tri[0]][axis] + mesh_.vertices[tri[1]][axis] + mesh_.vertices[tri[2]][axis];
  };
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centroid(a) < centroid(b); });
  const int left = build(begin, mid);
  const int right = build(mid, end);
  nodes_[static_cast<std::size_t>(id)].count = 0;
  nodes_[static_cast<std::size_t>(id)].left = left;
  nodes_[static_cast<std::size_t>(id)].right = right;
  return id;
}

void StlShape::closest(const Vec3& p, int node_id, double& best_d2, Vec3& best_point, Vec3& best_normal) const {
  const Node& node = nodes_[static_cast<std::size_t>(node_id)];
  if (box_distance2(node.box, p) >= best_d2) return;
  if (node.count > 0) {
    for (int i = node.first; i < node.first + node.count; ++i) {
      const int t = order_[static_cast<std::size_t>(i)];
      const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
      Feature f{};
      const Vec3 q = closest_on_triangle(p, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]], f);
      const double d2 = dot(p - q, p - q);
      if (d2 >= best_d2) continue;
      best_d2 = d2;
      best_point = q;
      const auto& en = edge_normals_[static_cast<std::size_t>(t)];
      switch (f) {
        case Feature::face: best_normal = face_normals_[static_cast<std::size_t>(t)]; break;
        case Feature::vertex0: best_normal = vertex_normals_[tri[0]]; break;
        case Feature::vertex1: best_normal = vertex_normals_[tri[1]]; break;
        case Feature::vertex2: best_normal = vertex_normals_[tri[2]]; break;
        case Feature::edge01: best_normal = en[0]; break;
        case Feature::edge12: best_normal = en[1]; break;
        case Feature::edge20: best_normal = en[2]; break;
      }
    }
    return;
  }
  // Visit the nearer child first so the bound tightens early.
  const double dl = box_distance2(nodes_[static_cast<std::size_t>(node.left)].box, p);
  const double dr = box_distance2(nodes_[static_cast<std::size_t>(node.right)].box, p);
  const int first = dl <= dr ? node.left : node.right;
  const int second = dl <= dr ? node.right : node.left;
  closest(p, first, best_d2, best_point, best_normal);
  closest(p, second, best_d2, best_point, best_normal);
}

double StlShape::signed_distance(const Vec3& p_m) const {
  double best_d2 = HUGE_VAL;
  Vec3 point;
  Vec3 normal;
  closest(p_m, 0, best_d2, point, normal);
  const double d = std::sqrt(best_d2);
  return dot(p_m - point, normal) > 0.0 ? d : -d;
}

}  // namespace hs::common
