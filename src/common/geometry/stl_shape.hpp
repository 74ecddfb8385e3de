// SPDX-License-Identifier: MIT
// The fluid region enclosed by a closed triangle surface (an STL from CAD or segmentation).
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include "common/geometry/shape.hpp"
#include "common/geometry/triangle_mesh.hpp"

namespace hs::common {

/// Exact signed distance to a closed, oriented triangle surface: the distance to the closest triangle from a
/// bounding-volume hierarchy, the sign from the angle-weighted pseudo-normal of the closest feature
/// (Baerentzen & Aanaes, IEEE TVCG 11:243, 2005), which is exact for closed manifolds.
class StlShape final : public Shape {
 public:
  /// Reads and checks the file (see require_closed_manifold); ConfigError on a bad surface.
  static std::shared_ptr<StlShape> load(const std::filesystem::path& file, double scale_to_m = 1.0);
  StlShape(TriangleMesh mesh, const std::string& source);

  [[nodiscard]] double signed_distance(const Vec3& p_m) const override;
  [[nodiscard]] Box3 bounds() const override { return nodes_.front().box; }
  [[nodiscard]] const TriangleMesh& mesh() const { return mesh_; }

 private:
  struct Node {
    Box3 box;
    int first;    // leaf: first index into order_; inner: left child (right = first + 1 is not assumed)
    int count;    // leaf: number of triangles; inner: 0
    int left;
    int right;
  };
  int build(int begin, int end);
  void closest(const Vec3& p, int node, double& best_d2, Vec3& best_point, Vec3& best_normal) const;

  TriangleMesh mesh_;
  std::vector<Vec3> face_normals_;                       // unit, outward
  std::vector<Vec3> vertex_normals_;                     // angle-weighted sums
  std::vector<std::array<Vec3, 3>> edge_normals_;        // per triangle edge (v_e, v_e+1): sum of the two faces
  std::vector<int> order_;                               // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace hs::common
