// SPDX-License-Identifier: MIT
// The typed input of the `shear-suspension` case: many cells at a hematocrit in simple shear between moving plates.
#pragma once

#include <cstdint>
#include <string>

#include "common/config/config_file.hpp"
#include "resolved/cases/cell_numerics.hpp"
#include "resolved/cases/plate_box.hpp"
#include "resolved/membrane/cell_contact.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {

/// Range of the cell-cell (and cell-wall) repulsion: 1 um, the collision threshold of Palabos-npFEM (2 lu at its
/// 0.5 um lattice; resolved-methods.md 1.4 table "Collision": a linear spring on a vertex closer than the threshold to
/// a foreign vertex), which HemoCell also applies between the membranes of different cells below a cut-off
/// (Zavodszky et al. 2017, Front Physiol 8:563, `setRepulsion(constant, cutoff)`).
inline constexpr double kCellContactRange_m = 1.0e-6;
/// Stiffness of that spring: 2e-5 N/m, the membrane-wall repulsion calibrated on the stenosis case (stenosis_cell_config:
/// 5 pN at 0.25 um inside the range holds a squeezed cell); k h^2 / m_vertex stays < 1 (checked).
inline constexpr double kCellContactStiffness_N_m = 2.0e-5;
/// Smallest vertex distance between cells at release: half the contact range, so the cells start apart and the spring
/// takes over smoothly where they start within its range.
inline constexpr double kPlacementGap_m = 0.5e-6;

/// Flow along x, walls at y = 0 (moving at -U/2) and y = H (+U/2), periodic in x and z.
/// [geometry] and [fluid]: the PlateBox.
struct ShearSuspensionConfig : PlateBox {
  double shear_rate_1_s = 0.0;      // [flow] shear_rate_1_s, or capillary Ca = mu gamma a / k_s
  double reynolds = 0.0;            // rho gamma H^2 / mu
  // [cells]
  double hematocrit = 0.0;
  std::uint64_t seed = 1;
  CellShapeKind shape = CellShapeKind::biconcave;
  double placement_gap_m = kPlacementGap_m;
  CellContactSpec contact;          // range and stiffness; the period is the box's
  MembraneConfig membrane;          // [membrane]
  CellNumerics numerics;            // [numerics]
  double max_time_s = 0.0, sample_every_s = 0.0;   // [run]
  double vtk_every_s = 0.0;         // [output]; 0: only the final frame
  long sample_every_steps = 0;      // derived
};

/// Reads and checks a `shear-suspension` case strictly. `quick` caps the run at 10 samples (CI). Throws
/// hs::common::ConfigError naming file and key.
ShearSuspensionConfig read_shear_suspension(hs::common::ConfigFile& file, bool quick);

}  // namespace hs::resolved
