// SPDX-License-Identifier: MIT
// The [numerics] keys of the time loop that every open CFD-DEM case (tube-open, open-geometry) reads alike.
#pragma once

#include "common/config/config_file.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// Reads dt_s, piso_correctors (default 4, not the FVM's 2: at viscous numbers nu dt / dx^2 of tens two PISO
/// correctors let an odd-even mode grow in the open tube and the bifurcation, four settle it; open_tube_test,
/// bifurcation_openings_test), pressure_coupling, n_coupling, end_time_s, average_from_fraction (default 0.5) and
/// checkpoint_every_wall_s (default 600, DESIGN.md) into the same-named fields of `c`.
template <class Config>
void read_loop_numerics(hs::common::ConfigSection& numerics, Config& c) {
  c.dt_s = numerics.positive("dt_s");
  c.piso_correctors = static_cast<int>(numerics.integer_in_or("piso_correctors", 1, 20, 4));
  c.pressure_coupling = pressure_coupling_from_name(numerics.one_of_or("pressure_coupling", {"piso", "projection"}, "piso"));
  c.n_coupling = static_cast<int>(numerics.integer_in("n_coupling", 1, 1000000));
  c.end_time_s = numerics.positive("end_time_s");
  c.average_from_fraction = numerics.number_in_or("average_from_fraction", 0.0, 0.95, 0.5);
  c.checkpoint_every_wall_s = numerics.positive_or("checkpoint_every_wall_s", 600.0);
}

}  // namespace hs::unresolved
