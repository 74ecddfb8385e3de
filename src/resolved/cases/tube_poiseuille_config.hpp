// SPDX-License-Identifier: MIT
// The typed input of the tube-poiseuille case, read strictly from case.toml, with its derived lattice values.
#pragma once

#include <array>
#include <string>

#include "common/config/config_file.hpp"
#include "resolved/lbm/boundary_links.hpp"
#include "resolved/lbm/collision_params.hpp"

namespace hs::resolved {

struct TubePoiseuilleConfig {
  // [geometry]
  double radius_m;
  double length_m;
  double box_width_m;               // square cross-section of the lattice box
  // [fluid]
  double density_kg_m3;
  double kinematic_viscosity_m2_s;
  // [flow]
  double reynolds;                  // Re = rho D U_max / mu = D U_max / nu, D = 2 R
  // [numerics]
  double dx_m;
  CollisionParams collision;
  WallRule wall;
  // [run]
  double steady_tolerance;          // relative change of u_max and Q per check interval
  long check_every_steps;
  long max_steps;
  // [output]
  long vtk_frames;                  // VTK frames while converging (the last one is the steady state)
  // derived
  double u_max_m_s;                 // analytic centre-line speed from Re
  double dt_s;
  double lattice_mach;
};

/// Reads and checks the whole case (strict: unknown keys, ranges, redundant keys, Mach, fit in the box).
/// `quick` coarsens dx by 2.5 (the CI version). Throws hs::common::ConfigError naming file and key.
TubePoiseuilleConfig read_tube_poiseuille(hs::common::ConfigFile& file, bool quick);

/// Global node counts: an odd number across so the tube axis passes through a node (u_max is then a node value).
[[nodiscard]] std::array<int, 3> tube_poiseuille_nodes(const TubePoiseuilleConfig& c);

}  // namespace hs::resolved
