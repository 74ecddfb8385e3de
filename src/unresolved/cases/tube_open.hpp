// SPDX-License-Identifier: MIT
// Case type "tube-open": RBC spheres injected at the inlet of a straight open tube (flow-rate inlet at z = 0,
// pressure outlet at z = L) and removed at its outlet: an open geometry (open_geometry.hpp) with a tube's few keys
// and two checks of its own (what goes in comes out; Fahraeus).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/case_request.hpp"
#include "common/check_list.hpp"
#include "common/config/config_file.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/coupling_model.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {

struct TubeOpenConfig {
  double diameter_m = 0.0;
  double length_m = 0.0;                 // inlet at z = 0, outlet at z = length_m
  FluidProperties fluid{};
  double inlet_mean_velocity_m_s = 0.0;  // plasma flow rate in over the tube's section, Q_p / (pi R^2)
  double discharge_hematocrit = 0.0;     // Ht_d of the inflow: RBC flux / (RBC + plasma flux)
  std::uint64_t seed = 1;
  ParticleParams particles{};
  CouplingModel model{};
  int cells_across = 10;
  double dt_s = 0.0;
  int piso_correctors = kCfdDemPisoCorrectors;   // loop_numerics.hpp
  PressureCoupling pressure_coupling = PressureCoupling::piso;
  int n_coupling = 1;
  double end_time_s = 0.0;
  double average_from_fraction = 0.5;    // the outlet's Ht_d and the tube's Ht_T over the last (1 - this) of the run
  double checkpoint_every_wall_s = 600.0;
  double vtk_every_s = 0.0;
  bool quick = false;

  [[nodiscard]] long steps() const;
  /// The time a cell moving at the mean velocity takes from inlet to outlet, L / U.
  [[nodiscard]] double transit_time_s() const { return length_m / inlet_mean_velocity_m_s; }
};

/// Reads a tube-open case file; ConfigError naming the key for an out-of-range value, a length that is not a whole
/// number of cells, a Courant number > 1 at the inlet's centreline speed or a DEM step above 0.1 min(t_Rayleigh,
/// t_Hertz). --quick: 20 CFD steps.
[[nodiscard]] TubeOpenConfig parse_tube_open(hs::common::ConfigFile& file, bool quick);

/// The tube as an open geometry: a Tube along z from 0 to L in the box around it, the openings "inlet" (the disc at
/// z = 0: flow rate pi R^2 U, Ht_d) and "outlet" (at z = L: 0 Pa), and the same numerics.
[[nodiscard]] OpenGeometryConfig open_geometry_of(const TubeOpenConfig& c);

/// The open tube's solvers (open_geometry_setup of open_geometry_of).
[[nodiscard]] CfdDemSetup tube_open_setup(const TubeOpenConfig& c);

/// Runs the case without a run folder (tests): every time-series row to `on_row`, checkpoints as `restart` says
/// (restart.rank: this process's rank in `comm`), on the z-slabs of `comm`'s ranks (one rank: the whole tube).
/// Returns summary.json's blocks (results, groups, numerics, timings), without the checks.
[[nodiscard]] nlohmann::json simulate_tube_open(const TubeOpenConfig& c, const std::function<void(const std::vector<double>&)>& on_row,
                                                const CfdDemRestart& restart = {}, MPI_Comm comm = MPI_COMM_SELF);

/// tube-open's own summary values (in the "results" block) from open-geometry's: discharge_hematocrit_inlet and _outlet,
/// outlet_vs_inlet_discharge_pct, tube_hematocrit (the domain's), tube_over_discharge_hematocrit (< 1: Fahraeus),
/// transits (= residence times, L / U), diameter_um, length_um, discharge_hematocrit_requested.
void add_tube_summary(const TubeOpenConfig& c, nlohmann::json& summary);

/// open-geometry's checks, and at steady state (not --quick) the outlet's discharge hematocrit within 2% of the inlet's
/// and the tube hematocrit below the inlet's discharge hematocrit (Fahraeus).
void check_tube_open(const TubeOpenConfig& c, const nlohmann::json& results, hs::common::CheckList& checks);

/// `hemoscale run` entry: exit 0 when the case's checks pass, 1 otherwise.
int run_tube_open(const hs::common::CaseRequest& request);

}  // namespace hs::unresolved
