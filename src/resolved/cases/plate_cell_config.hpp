// SPDX-License-Identifier: MIT
// The typed input of the two plate cases (one RBC between parallel walls): `shear` (walls moving at -U/2, +U/2)
// and `migration` (plane Poiseuille flow driven by a body force), with their derived lattice values.
#pragma once

#include <string>

#include "common/config/config_file.hpp"
#include "resolved/cases/cell_numerics.hpp"
#include "resolved/cases/plate_box.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {

enum class PlateFlow { shear, poiseuille };

/// Coordinates: flow along x, walls at y = 0 and y = H, periodic in x and z (z is the vorticity direction).
/// [geometry] and [fluid]: the PlateBox.
struct PlateCellConfig : PlateBox {
  PlateFlow flow = PlateFlow::shear;
  // [flow] (shear: shear_rate_1_s or capillary; migration: reynolds = rho H U_max / mu, Shi et al. 2014)
  double shear_rate_1_s = 0.0;      // shear: the imposed rate; migration: the wall shear rate 4 U_max / H
  double u_max_m_s = 0.0;           // migration: centreline velocity; shear: wall speed U/2
  double reynolds = 0.0;            // shear: rho gamma H^2 / mu (Couette, U = gamma H); migration: rho H U_max / mu
  /// shear with capillary: every viscosity raised by powers of two until the cell's Re_p and Stokes number are
  /// negligible (stokes_analogue.hpp), Ca, the viscosity ratio and Bq = eta_m / (mu a) kept. The viscosities above and
  /// the shear rate are the analogue's, already multiplied (divided) by analogue_viscosity_factor.
  bool stokes_analogue = false;
  double analogue_viscosity_factor = 1.0;
  // [cell]
  double initial_height = 0.5;      // y0 / H of the centroid at release
  int disc_axis = 1;                // 0 x, 1 y, 2 z: direction of the disc's symmetry axis at release
  CellShapeKind shape = CellShapeKind::biconcave;   // sphere: a capsule of radius kCellRadius_m (Ca's a)
  MembraneConfig membrane;          // [membrane]
  CellNumerics numerics;            // [numerics]
  // [run]
  double max_time_s = 0.0;
  bool stop_when_settled = false;   // shear: stop once the tank-treading revolutions are settled (max_time_s caps it)
  double sample_every_s = 0.0;
  double checkpoint_every_wall_s = 0.0;
  // [output]
  double vtk_every_s = 0.0;         // 0: only the final frame
  // [check] (optional; absent: the run measures only): what the run must show, else exit 1
  std::string expect_flow_mode;        // shear: "tumbling" | "tank-treading" | "intermediate" | "steady"; "" unchecked
  double period_over_jeffery_min = 0;  // shear, tumbling: band of the tumbling period / Jeffery's (0, 0: unchecked)
  double period_over_jeffery_max = 0;
  bool expect_toward_centreline = false;   // migration: the offset from the centreline shrinks, without turning back
  // derived
  long sample_every_steps = 0;
  long spin_up_steps = 0;           // migration: the drive is switched on smoothly over these steps (shear: 0)
};

/// RBC radius a = D0 / 2 = 3.91 um of the capillary number Ca = mu gamma_dot a / k_s (seed paper D0 = 7.82 um); with
/// [cell] shape = "sphere" the capsule's radius, so that Ca is the capsule's own.
inline constexpr double kCellRadius_m = 3.91e-6;

/// Reads and checks a `shear` or `migration` case strictly (`flow` picks which [flow] keys apply). `quick` caps the
/// run at 40 samples (CI). Throws hs::common::ConfigError naming file and key.
PlateCellConfig read_plate_cell(hs::common::ConfigFile& file, PlateFlow flow, bool quick);

}  // namespace hs::resolved
