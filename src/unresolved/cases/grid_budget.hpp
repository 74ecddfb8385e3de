// SPDX-License-Identifier: MIT
// The memory check of the tube-shaped CFD-DEM cases, made before the run folder exists or anything is allocated.
#pragma once

#include "common/config/config_file.hpp"
#include "common/geometry/shape.hpp"

namespace hs::unresolved {

/// Bytes per FVM cell: velocity, flux and work fields, the coupling fields, the cut-cell geometry, three momentum
/// matrices and the pressure matrix with hypre's AMG hierarchy. Peak resident memory of tube-plasma --quick runs over
/// the cell count (2026-12-02, process baseline included): 1.6 kB at 20 x 20 x 40 cells, 1.2 kB at 40 x 40 x 80,
/// 1.15 kB at 60 x 60 x 120; 2 kB bounds them.
inline constexpr double kFvmBytesPerCell = 2000.0;
/// Bytes per DEM particle: its columns, contact springs and neighbour-list entries (an upper bound).
inline constexpr double kDemBytesPerParticle = 2000.0;

/// Refuses (ConfigError, exit 2) a tube of `cells_across` FVM cells across `diameter_m` and `length_m` long, holding
/// about `particles` DEM spheres, that this machine's memory cannot hold; names [geometry] diameter_m and length_m and
/// [numerics] cells_across_diameter, with the micrometre hint for lengths of 1 mm or more.
void require_tube_grid_memory(const hs::common::ConfigFile& file, double diameter_m, double length_m, int cells_across,
                              double particles = 0.0);

/// The same for a box of FVM cells of size dx_m holding about `particles` spheres; names [numerics] dx_m and the box's
/// sides ([domain] box_min_m / box_max_m, or the shape's bounds when the case gives none).
void require_box_grid_memory(const hs::common::ConfigFile& file, const hs::common::Box3& box, double dx_m, double particles);

}  // namespace hs::unresolved
