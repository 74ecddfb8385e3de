// SPDX-License-Identifier: MIT
// A short-range membrane-wall repulsion: a linear contact spring that keeps membrane vertices out of a Shape's walls
// where the lattice is too coarse to resolve the lubrication film between a squeezed cell and the wall.
#pragma once

#include <span>
#include <vector>

#include "common/geometry/shape.hpp"
#include "common/vec3.hpp"

namespace hs::resolved {

struct WallRepulsionSpec {
  double range_m = 0.0;           // d0: vertices closer to the wall than this are pushed back; 0 switches it off
  double stiffness_N_m = 0.0;     // k_w of F = k_w (d0 - d) n
  double period_x_m = 0.0;        // positions are wrapped into [0, period) along x before the shape is asked (0: no)
};

/// F_v = k_w (d0 - d_v) n_v for every vertex v whose wall distance d_v = -signed_distance(x_v) is below d0 (also for
/// d_v < 0: the spring keeps pushing a vertex out of the wall), n_v = -grad signed_distance (into the fluid, by central
/// differences). Soft-contact penalty as in DPD/IBM cell codes (e.g. Fedosov et al. 2010 wall repulsion); it acts on
/// the membrane only, the fluid never sees it. The membrane takes it explicitly, so k_w h^2 / m_vertex must stay
/// well below 1 (checked by the case).
class WallRepulsion {
 public:
  WallRepulsion(const common::Shape& shape, const WallRepulsionSpec& spec);

  /// Adds the repulsion to `forces_N` (one per vertex) and records its total magnitude.
  void add_forces(std::span<const common::Vec3> x_m, std::vector<common::Vec3>& forces_N);
  [[nodiscard]] bool enabled() const { return spec_.range_m > 0.0 && spec_.stiffness_N_m > 0.0; }
  /// Sum of |F_v| of the last add_forces() call, newtons; and how many vertices it pushed.
  [[nodiscard]] double last_total_N() const { return last_total_N_; }
  [[nodiscard]] int last_vertices() const { return last_vertices_; }

 private:
  [[nodiscard]] common::Vec3 wrapped(common::Vec3 p) const;

  const common::Shape& shape_;
  WallRepulsionSpec spec_;
  double last_total_N_ = 0.0;
  int last_vertices_ = 0;
};

}  // namespace hs::resolved
