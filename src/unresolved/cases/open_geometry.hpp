// SPDX-License-Identifier: MIT
// Case type "open-geometry": RBC spheres through any shape of common/geometry (tube, stenosed tube, bifurcation,
// box, STL) between named openings: injected at its inlets, removed at its outlets, on the CFD-DEM skeleton.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/case_request.hpp"
#include "common/config/config_file.hpp"
#include "common/geometry/opening_condition.hpp"
#include "common/geometry/shape.hpp"
#include "unresolved/cases/bifurcation_study.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/coupling_model.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/cases/stenosis_study.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {

struct OpenGeometryConfig {
  std::shared_ptr<const hs::common::Shape> shape;      // [geometry]
  hs::common::Box3 box{};                                // [domain] box_min_m / box_max_m, or the shape's bounds
  std::vector<hs::common::OpeningCondition> openings;    // [openings.NAME], names sorted
  std::vector<double> discharge_hematocrit;              // one per opening: the inflow's Ht_d at an inlet, 0 at an outlet
  FluidProperties fluid{};
  std::uint64_t seed = 1;                                // [cells] seed: inlet k draws from seed + k
  ParticleParams particles{};
  CouplingModel model{};
  double dx_m = 0.0;
  double dt_s = 0.0;
  int piso_correctors = kCfdDemPisoCorrectors;           // loop_numerics.hpp
  PressureCoupling pressure_coupling = PressureCoupling::piso;
  int n_coupling = 1;
  double end_time_s = 0.0;
  double average_from_fraction = 0.5;   // averages over the last (1 - this) of the run
  double checkpoint_every_wall_s = 600.0;
  double vtk_every_s = 0.0;
  long min_cells_passed = 0;   // [check]: at least this many cells leave through the outlets (0: no check)
  bool quick = false;
  std::optional<BifurcationStudySpec> study;             // [study]: the bifurcation study's measurement on top
  std::optional<StenosisStudySpec> stenosis_study;       // [study] on a stenosed tube: the stenosis study's instead

  [[nodiscard]] long steps() const;
  /// Summed flow rate of the inlets (plasma, as the conditions prescribe it), m^3/s.
  [[nodiscard]] double inflow_m3_s() const;
};

/// Reads an open-geometry case file. ConfigError (exit 2) naming file, section, key and value for: a bad shape or
/// opening (one that does not cut the wall, an outlet with neither pressure_Pa nor flow_fraction, fractions that do
/// not add up), no pressure outlet (with cells in the openings' cells the fluxes only balance through one), an inlet
/// without discharge_hematocrit or with one outside [0, 0.6], discharge_hematocrit on an outlet, a Courant number
/// above 1 at an inlet's centreline, a DEM step above 0.1 min(t_Rayleigh, t_Hertz). --quick: 20 CFD steps.
[[nodiscard]] OpenGeometryConfig parse_open_geometry(hs::common::ConfigFile& file, bool quick);

/// Shape, grid (walls everywhere but the openings, each with its condition), DEM domain (the box, no periodic axis),
/// coupling (closures in the channel frame).
[[nodiscard]] CfdDemSetup open_geometry_setup(const OpenGeometryConfig& c);

/// Runs the case without a run folder (tests): every time-series row to `on_row`, checkpoints as `restart` says.
/// Returns summary.json's blocks (results, groups, numerics, timings), without the checks.
[[nodiscard]] nlohmann::json simulate_open_geometry(const OpenGeometryConfig& c,
                                                    const std::function<void(const std::vector<double>&)>& on_row,
                                                    const CfdDemRestart& restart = {});

/// `hemoscale run` entry: exit 0 when the case's checks pass (open_geometry_measurement.hpp), 1 otherwise.
int run_open_geometry(const hs::common::CaseRequest& request);

}  // namespace hs::unresolved
