// SPDX-License-Identifier: MIT
// The typed input of the `stenosis` case (one RBC through a periodic planar stenosed channel, seed paper section 3.2
// after Hsieh 2020), with its derived lattice values.
#pragma once

#include "common/config/config_file.hpp"
#include "common/geometry/stenosed_channel.hpp"
#include "resolved/cases/cell_numerics.hpp"
#include "resolved/cases/wall_repulsion.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {

/// Coordinates: flow along x, walls normal to y at y = H/2 +- h(x)/2 (h: cosine constriction of StenosedChannel),
/// periodic in x (length L) and z (width W). The throat (constriction centre) is at x = throat_x_m.
struct StenosisCellConfig {
  // [geometry]
  double height_m = 0.0;               // open wall-to-wall distance H
  double throat_height_m = 0.0;        // h_t
  double constriction_length_m = 0.0;  // L_c: the cosine narrowing spans throat_x +- L_c / 2
  double throat_x_m = 0.0;
  double length_m = 0.0;               // periodic box along x
  double width_m = 0.0;                // periodic box along z
  // [fluid]
  double density_kg_m3 = 0.0;
  double kinematic_viscosity_m2_s = 0.0;
  // [flow]
  double mean_velocity_m_s = 0.0;      // mean plasma velocity in the open channel: flow rate per width q = U H
  // [cell]
  double release_x_m = 0.0;            // centroid x at release (upstream of the constriction)
  double initial_height = 0.5;         // y0 / H of the centroid at release (slightly off-centre)
  int disc_axis = 2;                   // 0 x, 1 y, 2 z: direction of the disc's symmetry axis at release
  double stop_x_m = 0.0;               // the run ends when the centroid passes this x (downstream of the throat)
  MembraneConfig membrane;             // [membrane]
  CellNumerics numerics;               // [numerics]
  WallRepulsionSpec repulsion;         // [numerics] wall_repulsion_range_m, wall_repulsion_stiffness_N_m
  // [run]
  double max_time_s = 0.0;             // cap; the run normally stops at stop_x_m
  double sample_every_s = 0.0;
  double checkpoint_every_wall_s = 0.0;
  // [output]
  double vtk_every_s = 0.0;            // 0: only the final frame
  // derived
  long sample_every_steps = 0;
  long spin_up_steps = 0;              // the drive is switched on smoothly over these steps
  bool quick = false;                  // CI run: a few samples, no stop at stop_x_m required

  [[nodiscard]] double flow_rate_m2_s() const { return mean_velocity_m_s * height_m; }
  /// The channel as a Shape (x and z extents: the box).
  [[nodiscard]] common::StenosedChannelSpec channel() const;
};

/// Undeformed RBC diameter D0 = 7.82 um of D_i = L_i / D0 (seed paper section 3.2).
inline constexpr double kCellDiameter_m = 7.82e-6;

/// Reads and checks a `stenosis` case strictly. `quick` caps the run at 40 samples (CI). Throws
/// hs::common::ConfigError naming file and key.
StenosisCellConfig read_stenosis_cell(hs::common::ConfigFile& file, bool quick);

}  // namespace hs::resolved
