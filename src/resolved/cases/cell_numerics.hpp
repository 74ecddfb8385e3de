// SPDX-License-Identifier: MIT
// The [numerics] of every single-RBC coupled case (tube-cell, shear, migration): lattice units from the Mach limit,
// the tau cap, the membrane step and mass scaling, the IBM settings.
#pragma once

#include <string>

#include "common/config/config_file.hpp"
#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/lbm/boundary_links.hpp"
#include "resolved/lbm/collision_params.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {

struct CellNumerics {
  double dx_m = 0.0;
  double lattice_velocity = 0.0;      // reference velocity in lattice units: fixes dt (and so tau); lowered if tau > max_tau
  double max_tau = 0.0;
  double max_lattice_weissenberg = 0.0;   // bound on gamma_ref (tau - 1/2) dt (plate cases; see the .cpp)
  CollisionParams collision;          // tau derived
  WallRule wall = WallRule::bouzidi;
  int membrane_every = 2;
  double membrane_mass_factor = 0.0;  // numerical mass scaling of the membrane; 0 until derived (see the .cpp)
  IbmSettings ibm;
  TractionArea traction_area = TractionArea::scaled_membrane;   // which area the sampled fluid stress acts on
  bool drive_on_enclosed_volume = true;    // add the body-force drive's share the sampled tractions miss (CouplingSettings)
  MembraneForce membrane_force = MembraneForce::fluid_stress;   // sampled stress, or minus the IBM force (coupled_cell.hpp)
  Streaming streaming = Streaming::two_buffer;   // lattice storage: two buffers, or the in-place AA pattern (same results)
  /// Cytoplasm over plasma dynamic viscosity, from [cell] cytoplasm_viscosity_Pa_s (cytoplasm_viscosity.hpp); 1: one
  /// fluid inside and outside the cell, the lattice has one phase (bit for bit the runs before the cytoplasm).
  double viscosity_ratio = 1.0;
  CollisionParams inner_collision;    // derived when viscosity_ratio != 1: tau_in = 1/2 + ratio (tau - 1/2)
  double dt_s = 0.0;                  // derived
  double lattice_weissenberg = 0.0;   // derived: gamma_ref (tau - 1/2) dt, the lattice fluid's memory against the flow's
                                      // time (0 where the case gives no reference shear rate)
};

/// Reads [numerics] strictly (dx_m required, the rest with the defaults of the tube-cell campaign). tau and
/// time_step_s are derived: giving them is a ConfigError.
[[nodiscard]] CellNumerics read_cell_numerics(hs::common::ConfigSection numerics);

/// Derives dt = lattice_velocity dx / u_ref, tau = 1/2 + 3 nu dt / dx^2; if tau > max_tau, dt (and the lattice
/// velocity) are lowered so tau = max_tau. With a viscosity ratio > 1 the cap holds for the cytoplasm's tau, the
/// largest in the lattice: tau - 1/2 <= (max_tau - 1/2) / ratio outside. With a reference shear rate gamma_ref > 0 (the plate cases) tau is also
/// capped so that the lattice Weissenberg number gamma_ref (tau - 1/2) dt <= max_lattice_weissenberg: the lattice
/// fluid's stress relaxes over (tau - 1/2) dt, and that memory drove a cell in shear to the wall
/// (docs/resolved-coupling.md, "The lattice fluid's memory"). The membrane mass factor defaults to
/// max(1, 1.25 nu_lu k). Records time_step_s, tau (and lattice_weissenberg) as derived keys of `numerics`; without a
/// reference shear rate, giving max_lattice_weissenberg is a ConfigError.
void derive_cell_numerics(CellNumerics& n, double kinematic_viscosity_m2_s, double reference_velocity_m_s,
                          hs::common::ConfigSection numerics, double reference_shear_rate_1_s = 0.0);

/// A warning for the run's log when the IBM kernel reaches further from a vertex than the RBC's half-thickness: both
/// faces of the disc then force the same fluid, and past its membrane transient the cell folds into a compact shape
/// (docs/resolved-coupling.md, "The IBM kernel's width"). Empty when the kernel is narrow enough, and for a sphere,
/// which has no thin disc to fold across.
[[nodiscard]] std::string kernel_width_warning(DeltaKernel kernel, double dx_m,
                                               CellShapeKind shape = CellShapeKind::biconcave);

}  // namespace hs::resolved
