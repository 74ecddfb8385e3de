// SPDX-License-Identifier: MIT
// The closures' "tube" in any channel: lift direction, channel radius and mean velocity from the geometry.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "common/geometry/shape.hpp"
#include "common/vec3.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// What the geometry says about the channel around a point (docs/cfd-dem.md "Closure inputs without a tube").
struct ChannelPoint {
  hs::common::Vec3 wall_normal;   // unit gradient of the signed distance: towards the nearest wall; zero on the medial axis
  double wall_distance_m = 0.0;   // minus the signed distance (> 0 in the fluid)
  double channel_radius_m = 0.0;  // R_c: radius of the largest sphere in the channel touching the wall where x's normal meets it
  hs::common::Vec3 centre_m;      // that sphere's centre, on the channel's medial axis
};

/// The channel at x_m: the normal from the signed distance's central differences (step 1e-3 length_scale_m), R_c as
/// the maximum of the wall distance along the line from x against the normal (marched in steps of length_scale_m / 4,
/// then refined by golden section). In a straight tube: the radial unit vector, R and the axis point, exactly.
[[nodiscard]] ChannelPoint channel_point(const hs::common::Shape& shape, const hs::common::Vec3& x_m, double length_scale_m);

/// The flow through the channel's section at a point: its direction (the fluid velocity at the centre) and the mean
/// velocity of the mixture (plasma and cells) along it over the section (in a tube: Q / A, with Q the blood flow).
struct ChannelFlow {
  hs::common::Vec3 direction;     // unit; zero where the centre's fluid is at rest
  double mean_velocity_m_s = 0.0;
};

/// The section's mean over the grid cells of a slab three cells thick across the flow, out to R_c (+ one cell for the
/// cut cells at a wall), each weighted with its fluid volume.
[[nodiscard]] ChannelFlow channel_flow(const FvmSolver& fluid, const ChannelPoint& at);

/// The channel frame of a run: the geometry per grid cell, computed on first use and kept (the walls do not move),
/// and the section's flow, computed at most once per step for each cell that holds a section centre (so a tube's
/// layer of cells costs one section mean, not one per cell).
class ChannelFrame {
 public:
  explicit ChannelFrame(const FvmSolver& fluid);

  /// Lift direction at x itself (the wall normal there; zero on the medial axis).
  [[nodiscard]] hs::common::Vec3 wall_normal(const hs::common::Vec3& x_m) const;
  /// The channel and its flow at the centre of the cell holding x (call new_step() when the fluid has moved).
  struct Local {
    double channel_radius_m;
    ChannelFlow flow;
  };
  [[nodiscard]] Local at(const hs::common::Vec3& x_m);
  void new_step() { ++step_; }
  /// On z-slabs, collective, after new_step() and before at(): the sections of the cells holding `xs` (this rank's
  /// points; every one in this block) and every other rank's, each summed over the ranks' cells, so a section may
  /// reach any plane of the grid. A section is keyed by the whole grid's index of the cell holding its centre (as one
  /// rank keys it), its direction from the rank whose block holds that centre.
  void prepare_sections(const std::vector<hs::common::Vec3>& xs);

 private:
  /// The channel point of a cell (flat index of its (i, j, k)), and of the cell holding its centre, on first use.
  const ChannelPoint& cell_point(const std::array<int, 3>& cell, std::size_t flat);

  const FvmSolver& fluid_;
  std::vector<ChannelPoint> points_;
  std::vector<char> have_point_;
  std::vector<std::size_t> section_;   // per cell: the cell holding its medial centre (whose point gives the flow)
  std::vector<ChannelFlow> flows_;
  std::vector<long> flow_step_;
  long step_ = 0;
  // On slabs: per block cell, the whole grid's index of its section's cell (-1: not yet), and this step's flows.
  std::vector<std::int64_t> section_key_;
  std::map<std::int64_t, ChannelFlow> slab_flows_;
  std::map<std::int64_t, ChannelPoint> key_points_;   // the channel point of a section's cell (geometry: kept)
  [[nodiscard]] std::int64_t section_key(const std::array<int, 3>& cell, std::size_t flat);
};

}  // namespace hs::unresolved
