// SPDX-License-Identifier: MIT
// Case type "tube-pries": RBC spheres in plasma in a periodic tube (CFD-DEM), Ht_d and mu_rel vs Pries 1992.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "closures/closure_registry.hpp"
#include "closures/wall_correction.hpp"
#include "common/case_request.hpp"
#include "common/progress.hpp"
#include "unresolved/cases/coupling_model.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/coupling/suspension_viscosity.hpp"
#include "unresolved/dem/particle_params.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

struct TubePriesConfig {
  double diameter_m = 0.0;
  double length_m = 0.0;
  double tube_hematocrit = 0.0;          // Ht_c: RBC volume / tube volume at insertion
  FluidProperties fluid{};
  double pressure_gradient_Pa_m = 0.0;   // dp/dz < 0
  ParticleParams particles{};
  int cells_across = 10;
  double dt_s = 0.0;                     // CFD step
  double vtk_every_s = 0.0;              // [output] vtk_every_s; 0: only the final frame
  PressureCoupling pressure_coupling = PressureCoupling::piso;   // [numerics] pressure_coupling
  int piso_correctors = kCfdDemPisoCorrectors;   // [numerics] piso_correctors (loop_numerics.hpp)
  int n_coupling = 1;                    // DEM steps per CFD step
  double end_time_s = 0.0;               // the shortest run; from here on it is checked for a steady state
  double max_end_time_s = 0.0;           // and continues until steady, at most to this (equal: a fixed length)
  double average_from_fraction = 0.5;    // Ht_d and Q are averaged over the last (1 - this) of the run
  double steady_tolerance = 0.02;        // steady when the trends of Ht_d and mu_rel over that window move them less
  bool void_fraction_rate = false;       // d(eps)/dt source (see CouplingSettings::void_fraction_rate)
  hs::closures::ClosureSpec drag{}, lift{}, deformation{};   // model "none": no lift / DI = 0
  hs::closures::WallCorrection wall_correction = hs::closures::WallCorrection::none;   // confinement factor on the drag
  bool self_induced_correction = false;  // closures get u_f - M F (CouplingSettings::self_induced_correction)
  SuspensionViscosity suspension_viscosity = SuspensionViscosity::none;   // the cells' stress (suspension_viscosity.hpp)
  double smoothing_length_m = 0.0;       // the coupling fields' smoothing length (CouplingSettings), m; 0: none
  bool buoyancy_over_footprint = false;  // CouplingSettings::buoyancy_over_footprint
  double checkpoint_every_wall_s = 600.0;   // wall-clock interval between restart files (and one at the end)
  std::uint64_t seed = 1;

  /// The [coupling] keys above as one model (coupling_model.hpp).
  [[nodiscard]] CouplingModel coupling_model() const {
    return {.void_fraction_rate = void_fraction_rate, .drag = drag, .lift = lift, .deformation = deformation,
            .wall_correction = wall_correction, .self_induced_correction = self_induced_correction,
            .suspension_viscosity = suspension_viscosity, .smoothing_length_m = smoothing_length_m,
            .buoyancy_over_footprint = buoyancy_over_footprint};
  }
};

/// Measured by simulate_tube_pries; the Pries 1992 fields (0 until then) are filled on the validation side by
/// add_pries_comparison (validate/tube_pries_comparison.hpp), so no solver-side code reads analysis/.
struct TubePriesResult {
  nlohmann::json summary;                // every measured value (summary.json), and the reference once compared
  double ht_d = 0.0;
  double mu_rel = 0.0;
  double ht_d_pries = 0.0;
  double mu_rel_pries = 0.0;
  double ht_d_error_pct = 0.0;
  double mu_rel_error_pct = 0.0;
};

/// Reads a tube-pries case file. Bad input (impossible hematocrit, unknown closure, Courant or DEM-step
/// violation, a length that is not a whole number of cells) is a ConfigError naming the key.
[[nodiscard]] TubePriesConfig parse_tube_pries(hs::common::ConfigFile& file, bool quick);

/// Time series sample handed to the observer every CFD step.
struct TubePriesSample {
  double time_s, q_blood_m3_s, q_rbc_m3_s, ht_d, pressure_iterations;
};

/// Where and whether the coupled run keeps restart files (common::Checkpoint, one per rank, replaced atomically):
/// fluid fields, particles with their contact springs, coupling state, insertion result and the samples so far.
struct TubePriesRestart {
  std::filesystem::path dir;   // checkpoint folder; empty: no checkpoints
  bool resume = false;         // continue from the checkpoint in dir
  int rank = 0;                // this process's rank in the run's communicator (names its checkpoint file)
  bool distributed = false;    // the tube on MPI_COMM_WORLD's z-slabs, one per rank; otherwise on this process alone
};

class CfdDemFrames;

/// Runs the plasma-only reference and the coupled tube on the CFD-DEM skeleton (tube_pries_measurement.cpp); throws ConfigError for inputs found bad on the way
/// (insertion impossible, particles outside the tube, DEM step, a checkpoint of another case). With restart.dir a
/// checkpoint is written every c.checkpoint_every_wall_s and at the end; with restart.resume the run continues
/// from it up to c.max_end_time_s (which may be later than the saved run's): the samples before the checkpoint are
/// handed to `observe` again first, and Ht_d and Q are averaged over the whole series as if never stopped.
/// `frames` (may be null) is handed the solvers after every CFD step (ParaView output; reads only); `progress` (may be
/// null) is updated with the CFD steps done, out of those up to max_end_time_s.
[[nodiscard]] TubePriesResult simulate_tube_pries(const TubePriesConfig& c,
                                                  const std::function<void(const TubePriesSample&)>& observe,
                                                  const TubePriesRestart& restart = {}, CfdDemFrames* frames = nullptr,
                                                  hs::common::Progress* progress = nullptr);

/// `hemoscale run` entry: the run on the CFD-DEM skeleton, then the Pries comparison and the checks
/// (validate/tube_pries_checks.hpp): exit 0 when they pass, 1 when one fails. Defined on the validation side,
/// validate/tube_pries_run.cpp (library hs_validate), because the comparison reads analysis/.
int run_tube_pries(const hs::common::CaseRequest& request);

}  // namespace hs::unresolved
