// SPDX-License-Identifier: MIT
// The typed input of the tube-cell case (one RBC in the periodic campaign tube), with its derived lattice values.
#pragma once

#include "common/config/config_file.hpp"
#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/lbm/boundary_links.hpp"
#include "resolved/lbm/collision_params.hpp"
#include "resolved/membrane/membrane_parameters.hpp"

namespace hs::resolved {

enum class TubeCellSetup { drag, lift };

struct TubeCellConfig {
  // [geometry]
  double radius_m;
  double length_m;
  // [fluid]
  double density_kg_m3;
  double kinematic_viscosity_m2_s;
  // [flow]
  double reynolds;                  // Re = rho D U_max / mu, D = 2 R (seed paper section 4)
  // [cell]
  TubeCellSetup setup;
  double radial_position;           // r* = r / R of the centre of mass
  double disc_tilt_rad = 0.0;       // start: the disc normal's angle from the vorticity e_theta toward the flow (0: rolling)
  MembraneConfig membrane;          // [membrane]
  // [numerics]
  double dx_m;
  double lattice_velocity;          // U_max in lattice units: fixes dt (and so tau); lowered if tau > max_tau
  double max_tau;
  CollisionParams collision;        // tau derived
  double viscosity_ratio = 1.0;     // CellNumerics: cytoplasm / plasma ([cell] cytoplasm_viscosity_Pa_s)
  CollisionParams inner_collision;  // CellNumerics: the cytoplasm's (viscosity_ratio != 1)
  WallRule wall;
  Streaming streaming = Streaming::two_buffer;
  int membrane_every;
  double membrane_mass_factor;      // numerical mass scaling of the membrane (see tube_cell_config.cpp)
  IbmSettings ibm;
  TractionArea traction_area;       // which area the sampled fluid stress acts on
  bool drive_on_enclosed_volume = true;    // CellNumerics: the body-force share the sampled tractions miss
  MembraneForce membrane_force = MembraneForce::fluid_stress;   // CellNumerics: stress sampling or the IBM reaction
  bool extrapolate_lattice_memory = false;   // a second stage at half the time step; results extrapolated to Wi -> 0
  // [run]
  double max_time_s;                // cap on simulated time
  double max_jeffery_periods;       // or the cap in Jeffery periods at r* (0: not given), counted after the membrane
                                    // transient (kMembraneTransientTimes relaxation times)
  double sample_every_s;            // time-series sampling
  int settle_periods;               // whole periods that must agree before stopping (and are averaged)
  double settle_spread;             // relative spread of the per-period means that counts as settled
  double lift_settle_spread;        // the same for Cl in a lift run (the lift is noisier than DI; tube_cell_series.cpp)
  double checkpoint_every_wall_s;
  // [output]
  double vtk_every_s;               // 0: only the final frame
  // derived
  double u_max_m_s;
  double dt_s;
  long sample_every_steps;
  long spin_up_steps;               // the drive is switched on smoothly over these steps
  double transient_s;               // start-up discarded before settling is judged (kMembraneTransientTimes tau_m)
  bool starts_steady = false;       // a stage that starts from a settled, steady (not periodic) cell: its steady
                                    // window need not span a Jeffery period (no tumble to rule out)
};

/// Jeffery period 2 pi (r_e + 1/r_e) / gamma_dot of a spheroid of aspect ratio r_e = 0.37 (the RBC's thickness over
/// diameter; Jeffery 1922), i.e. 19.3 / gamma_dot, at the undisturbed shear rate at the cell's r*; infinite on the axis.
double jeffery_period_s(const TubeCellConfig& c);

/// RBC reference diameter D0 (seed paper section 3.2, Evans-Fung shape); Ca and the relaxation time use a = D0 / 2.
inline constexpr double kCellDiameterD0_m = 7.82e-6;

/// Kelvin-Voigt relaxation time of the membrane, zeta a^2 / k_s: its deformation friction against its shear modulus
/// over the cell radius a = D0 / 2 = 3.91 um (0.17 s with the defaults; ~0.1-0.3 s measured for RBC shape recovery,
/// Hochmuth et al. 1979). The cell's shape needs a few of these to respond to the flow; 0 without friction.
double membrane_relaxation_time_s(const TubeCellConfig& c);

/// Membrane relaxation times discarded as start-up transient before a tube-cell run may settle (e^-3 = 5 % left).
inline constexpr double kMembraneTransientTimes = 3.0;

/// Spin-up times that start the half-time-step stage (its membrane starts settled, the fluid at rest): one to carry the
/// drive (4 R^2 / nu, the spin-up), two more for the flow around the cell and its tractions to follow.
inline constexpr double kHalfTimeStepStageSpinUps = 3.0;

/// The second stage of a run with extrapolate_lattice_memory (docs/resolved-coupling.md, "Extrapolating the lattice
/// memory"): the same case at half the time step, so tau - 1/2 halves at the same dx and the lattice Weissenberg number
/// gamma (tau - 1/2) dt falls to a quarter; it starts from the first stage's settled membrane, so its start-up is
/// kHalfTimeStepStageSpinUps spin-ups instead of the membrane transient, and it has as long after it as the first.
[[nodiscard]] TubeCellConfig half_time_step_stage(const TubeCellConfig& c);

/// The value at lattice Weissenberg number 0 from two stages, linear in Wi (measured linear at r* 0.7, Re 0.5 over
/// Wi 3.5e-4 ... 1.75e-3 at the healthy viscosity ratio: data/resolved-v2/checks/2026-12-02_wi_ratio5.85/).
[[nodiscard]] double extrapolated_to_zero_weissenberg(double value_1, double wi_1, double value_2, double wi_2);

/// Reads and checks the whole case strictly. `quick` caps the run at 40 samples (CI); dx is kept, because at
/// dx = 2 um the 258-vertex mesh is denser than the lattice (mean edge ~0.35 lu) and multi-direct forcing
/// diverges (measured: Mach watchdog after 100 steps; resolved-methods.md 8.6).
/// Throws hs::common::ConfigError naming file and key.
TubeCellConfig read_tube_cell(hs::common::ConfigFile& file, bool quick);

}  // namespace hs::resolved
