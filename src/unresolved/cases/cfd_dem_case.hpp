// SPDX-License-Identifier: MIT
// The skeleton every unresolved (CFD-DEM) case runs on: solvers built from the case's geometry, the coupled step
// as named stages with timers, the time series, checkpoints with Ctrl-C/SIGTERM and --resume. A case adds only its
// measurement (CfdDemMeasurement).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <mpi.h>
#include <nlohmann/json.hpp>

#include "common/geometry/shape.hpp"
#include "common/io/checkpoint.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "common/progress.hpp"
#include "common/time_loop.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/fvm/fvm_grid.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// What a case's geometry and numerics give the skeleton; the solvers are built from it in this order.
struct CfdDemSetup {
  std::shared_ptr<const hs::common::Shape> shape;   // the fluid region (walls of the FVM and the DEM)
  FvmGridSpec grid;                           // box, dx, boundary condition of each box side
  FluidProperties fluid;
  PisoSettings piso;
  FlowDrive drive;
  DemSettings dem;                            // particles, DEM domain (its periodic axes), DEM step
  CouplingSettings coupling;
  CouplingClosures closures;
};

/// The solvers of one run: grid, fluid, DEM and coupling, all over one shape. On a communicator of several ranks
/// they are built on z-slabs of the grid's cells (docs/cfd-dem.md "Distributed CFD-DEM"): the grid, the fluid and
/// the DEM each hold this rank's slab, and every step is collective; on one rank the whole grid, as before.
class CfdDemSolvers {
 public:
  explicit CfdDemSolvers(CfdDemSetup setup, MPI_Comm comm = MPI_COMM_SELF);
  CfdDemSolvers(const CfdDemSolvers&) = delete;
  CfdDemSolvers& operator=(const CfdDemSolvers&) = delete;

  [[nodiscard]] const hs::common::Shape& shape() const { return *shape_; }
  [[nodiscard]] const FvmGrid& grid() const { return *grid_; }
  [[nodiscard]] FvmSolver& fluid() { return *fluid_; }
  [[nodiscard]] const FvmSolver& fluid() const { return *fluid_; }
  [[nodiscard]] DemSystem& dem() { return *dem_; }
  [[nodiscard]] const DemSystem& dem() const { return *dem_; }
  [[nodiscard]] CfdDemCoupling& coupling() { return *coupling_; }
  [[nodiscard]] const CfdDemCoupling& coupling() const { return *coupling_; }
  [[nodiscard]] const CouplingSettings& coupling_settings() const { return coupling_settings_; }
  [[nodiscard]] MPI_Comm comm() const { return comm_; }
  /// This rank's slab of the DEM (null on one rank).
  [[nodiscard]] const DemSlabs* slabs() const { return dem_slabs_.get(); }

 private:
  std::shared_ptr<const hs::common::Shape> shape_;
  MPI_Comm comm_;
  std::unique_ptr<hs::common::CartesianDecomposition> decomposition_;   // several ranks: z-slabs of the cells
  std::unique_ptr<DemSlabs> dem_slabs_;
  std::unique_ptr<FvmGrid> grid_;
  std::unique_ptr<DemSystem> dem_;
  std::unique_ptr<FvmSolver> fluid_;
  CouplingSettings coupling_settings_;
  std::unique_ptr<CfdDemCoupling> coupling_;
};

/// What a case measures on the skeleton. The skeleton keeps the rows (summary averages, checkpoint, resume).
class CfdDemMeasurement {
 public:
  virtual ~CfdDemMeasurement() = default;
  /// Written in checkpoints; a checkpoint of another case type is refused.
  [[nodiscard]] virtual std::string case_type() const = 0;
  /// timeseries.csv's unit-suffixed header; sample() returns one value per column.
  [[nodiscard]] virtual std::vector<std::string> columns() const = 0;
  /// Before the run, fresh or resumed (e.g. a plasma-only reference run on the same grid).
  virtual void prepare(CfdDemSolvers& /*run*/) {}
  /// A fresh run, before the first step: cells in, the coupling's reference velocity.
  virtual void start(CfdDemSolvers& run) = 0;
  /// Stages of the case inside the step, run after the DEM sub-steps and before the particles go on the grid
  /// (e.g. cells in and out at openings); added to the loop by name, so they are timed like the coupling's.
  virtual void add_stages(hs::common::TimeLoop& /*loop*/, CfdDemSolvers& /*run*/) {}
  /// After every CFD step: the time-series row.
  [[nodiscard]] virtual std::vector<double> sample(const CfdDemSolvers& run) = 0;
  /// After every row: whether the run has measured what it runs for (e.g. a steady state) before the loop's last
  /// step; the loop then stops after this step. A function of the rows only, so a resumed run decides alike.
  [[nodiscard]] virtual bool finished(const std::vector<std::vector<double>>& /*rows*/) const { return false; }
  /// The case's own restart state beyond the rows (the skeleton writes them as "series").
  virtual void write_state(hs::common::Checkpoint& /*cp*/) const {}
  virtual void read_state(const hs::common::Checkpoint& /*cp*/) {}
  /// summary.json's blocks from the whole series: "results" (measured values), "groups" (dimensionless groups) and
  /// "numerics" (model choices, averaging); the skeleton adds its groups, steps and "timings".
  [[nodiscard]] virtual nlohmann::json summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const = 0;
};

/// Where and whether the run keeps restart files (common::Checkpoint, one per rank, replaced atomically).
struct CfdDemRestart {
  std::filesystem::path dir;   // checkpoint folder; empty: no checkpoints
  bool resume = false;         // continue from the checkpoint in dir
  int rank = 0;
};

struct CfdDemLoopOptions {
  long steps = 1;                          // CFD steps of the whole run at most (a resumed run continues up to it;
                                           // CfdDemMeasurement::finished may stop it earlier)
  double checkpoint_every_wall_s = 600.0;  // and one at the end, and one on Ctrl-C/SIGTERM
  CfdDemRestart restart{};
  std::function<void(const std::vector<double>&)> on_row;   // every row, the saved ones first on a resume
  /// After every CFD step, with the step count and whether it is the last (ParaView frames; reads only). The last
  /// is options.steps or the step after which the measurement said finished.
  std::function<void(const CfdDemSolvers&, long, bool)> after_step;
  hs::common::Progress* progress = nullptr;
};

struct CfdDemOutcome {
  std::vector<std::vector<double>> rows;   // the whole series, saved rows included
  nlohmann::json summary;                  // the measurement's blocks, with the skeleton's groups, steps and timings
  std::string timing_table;                // wall seconds per stage, for the log
  double prepare_seconds = 0.0;            // the measurement's prepare() (e.g. a plasma-only reference run)
};

/// Runs `m` on `run` up to options.steps or until m.finished: prepare, then start (fresh) or the checkpoint (resume), the stages
/// dem_substeps, the case's, particles_to_grid, fluid_step, fluid_to_particles, measure; a checkpoint every
/// checkpoint_every_wall_s and at the end; on SIGINT/SIGTERM a checkpoint and RunInterrupted. ConfigError for a
/// missing checkpoint or one of another case type or length.
[[nodiscard]] CfdDemOutcome run_cfd_dem(CfdDemSolvers& run, CfdDemMeasurement& m, const CfdDemLoopOptions& options);

}  // namespace hs::unresolved
