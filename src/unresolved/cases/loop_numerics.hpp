// SPDX-License-Identifier: MIT
// The [numerics] keys of the time loop that the CFD-DEM cases read alike (all of them for tube-open and open-geometry).
#pragma once

#include "common/config/config_file.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// PISO correctors of every CFD-DEM case, 4 by default, not the FVM's 2: at viscous numbers nu dt / dx^2 of tens two
/// correctors let an odd-even mode grow wherever the flow is disturbed (the open tube, the bifurcation, one sphere in
/// the periodic tube at 15 cells across D = 30 um), four settle it (open_tube_test, bifurcation_openings_test,
/// tube_pries_lone_sphere_test).
inline constexpr int kCfdDemPisoCorrectors = 4;

/// [numerics] piso_correctors (1-20, default kCfdDemPisoCorrectors).
inline int read_piso_correctors(hs::common::ConfigSection& numerics) {
  return static_cast<int>(numerics.integer_in_or("piso_correctors", 1, 20, kCfdDemPisoCorrectors));
}

/// Reads dt_s, piso_correctors (read_piso_correctors), pressure_coupling, n_coupling, end_time_s,
/// average_from_fraction (default 0.5) and checkpoint_every_wall_s (default 600, DESIGN.md) into the same-named
/// fields of `c`.
template <class Config>
void read_loop_numerics(hs::common::ConfigSection& numerics, Config& c) {
  c.dt_s = numerics.positive("dt_s");
  c.piso_correctors = read_piso_correctors(numerics);
  c.pressure_coupling = pressure_coupling_from_name(numerics.one_of_or("pressure_coupling", {"piso", "projection"}, "piso"));
  c.n_coupling = static_cast<int>(numerics.integer_in("n_coupling", 1, 1000000));
  c.end_time_s = numerics.positive("end_time_s");
  c.average_from_fraction = numerics.number_in_or("average_from_fraction", 0.0, 0.95, 0.5);
  c.checkpoint_every_wall_s = numerics.positive_or("checkpoint_every_wall_s", 600.0);
}

}  // namespace hs::unresolved
