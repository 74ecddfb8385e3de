// SPDX-License-Identifier: MIT
// The overlap tests shared by the cell placements (issue #24): rigid copies of one rest mesh, each at a pose (rotation
// and centre) and a common scale about its centre, against the walls, a vertex gap and each other's insides.
#pragma once

#include <array>
#include <random>
#include <vector>

#include "common/vec3.hpp"
#include "resolved/cases/cell_placement.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved::placement {

using Rotation = std::array<common::Vec3, 3>;   // rows
using Quaternion = std::array<double, 4>;       // w, x, y, z (unit)

/// A cell's rotation (from its rest frame) and centre; the centre stays inside the box along periodic axes.
struct Pose {
  Quaternion q{1.0, 0.0, 0.0, 0.0};
  common::Vec3 centre;
};

[[nodiscard]] Rotation rotation_of(const Quaternion& q);
/// Uniform random rotation from a uniform unit quaternion (Shoemake 1992, Graphics Gems III): three draws.
[[nodiscard]] Quaternion random_quaternion(std::mt19937_64& rng);
/// q turned further by `angle` about the unit `axis` (left product), renormalised.
[[nodiscard]] Quaternion turned(const Quaternion& q, const common::Vec3& axis, double angle);

/// Which voxels of the rest mesh's box (centred on its centroid) lie inside it.
class InsideMap {
 public:
  InsideMap(const std::vector<common::Vec3>& body, const std::vector<std::array<int, 3>>& triangles);
  /// p relative to the mesh's centroid, in its own (rest) frame.
  [[nodiscard]] bool inside(const common::Vec3& p) const;

 private:
  [[nodiscard]] std::size_t index(int i, int j, int k) const;
  std::array<double, 3> lo_{};
  std::array<double, 3> hi_{};
  std::array<int, 3> n_{};
  double h_ = 0.0;
  std::vector<char> inside_;
};

/// The rest mesh about its centroid, the box, the gap and the wall clearance.
class CellGeometry {
 public:
  CellGeometry(const TriangleMesh& rest, const PlacementBox& box, double gap_m, double wall_clearance_m);
  [[nodiscard]] const PlacementBox& box() const { return box_; }
  [[nodiscard]] double gap_m() const { return gap_m_; }
  [[nodiscard]] double cell_volume_m3() const { return cell_volume_m3_; }
  /// Largest distance of a rest vertex from the centroid.
  [[nodiscard]] double radius_m() const { return radius_m_; }
  /// The vertices of a cell at `pose`, `scale` times its rest size; false at the first vertex closer than the clearance
  /// to a wall (x is then incomplete). At scale 1 exactly centre + R b.
  bool vertices_within_walls(const Pose& pose, double scale, std::vector<common::Vec3>& x) const;
  /// Whether a vertex of either cell lies inside the other (both at `scale`); pairs whose bounding spheres do not
  /// meet are not tested.
  [[nodiscard]] bool interpenetrate(const Pose& a, const Pose& b, double scale) const;
  [[nodiscard]] common::Vec3 minimum_image(common::Vec3 d) const;
  /// The centre moved back into the box along the periodic axes.
  [[nodiscard]] common::Vec3 wrapped(common::Vec3 c) const;

 private:
  PlacementBox box_;
  double gap_m_;
  double wall_clearance_m_;
  std::vector<common::Vec3> body_;
  InsideMap inside_;
  double radius_m_ = 0.0;
  double cell_volume_m3_ = 0.0;
};

/// Cells' vertices in bins no smaller than the gap (periodic axes: a whole number of bins per period), each tagged
/// with its cell, so that one cell can be taken out, moved and put back.
class VertexBins {
 public:
  VertexBins(const PlacementBox& box, double gap_m);
  void add(int cell, const std::vector<common::Vec3>& x);
  void remove(int cell, const std::vector<common::Vec3>& x);
  /// Empties every bin (keeping their storage).
  void clear();
  /// Whether a stored vertex of a cell other than `self` lies within the gap of p (minimum image).
  [[nodiscard]] bool any_within(const common::Vec3& p, int self) const;

 private:
  struct Entry {
    common::Vec3 p;   // moved into the box along the periodic axes
    int cell;
  };
  [[nodiscard]] int bin_along(int axis, double coordinate) const;
  [[nodiscard]] common::Vec3 wrapped(common::Vec3 p) const;
  [[nodiscard]] std::size_t flat(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * count_[1] + j) * count_[2] + k;
  }
  PlacementBox box_;
  double gap2_;   // the gap squared
  std::array<int, 3> count_{};
  std::array<double, 3> size_{};
  std::vector<std::vector<Entry>> bins_;
  std::vector<std::size_t> filled_;   // bins that received a vertex since the last clear()
  std::vector<char> listed_;          // whether a bin is in filled_
};

/// Whether the cells at `poses`, all at `scale`, keep the walls' clearance, the gap and each other's insides
/// (`scratch`: bins for the geometry's box and gap, emptied first).
[[nodiscard]] bool all_clear(const CellGeometry& g, const std::vector<Pose>& poses, double scale, VertexBins& scratch);

/// Random sequential addition of n cells at `scale`: uniformly random rotations and centres, each accepted when clear
/// of the walls and of the cells before it. Returns the poses placed (fewer than n when one found no place in
/// `attempts_per_cell` tries); `attempts` counts every try.
[[nodiscard]] std::vector<Pose> random_sequential_addition(const CellGeometry& g, long n, double scale,
                                                           int attempts_per_cell, std::mt19937_64& rng, long& attempts);

}  // namespace hs::resolved::placement
