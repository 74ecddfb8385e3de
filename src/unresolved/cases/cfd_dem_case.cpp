// SPDX-License-Identifier: MIT
// The unresolved case skeleton: solvers from the setup, the staged loop, rows, checkpoints and signals.
#include "unresolved/cases/cfd_dem_case.hpp"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/stop_request.hpp"

namespace hs::unresolved {
namespace {

int ranks_of(MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  return ranks;
}

void write_checkpoint(const CfdDemSolvers& run, const CfdDemMeasurement& m, const std::vector<std::vector<double>>& rows,
                      const CfdDemRestart& restart) {
  hs::common::Checkpoint cp;
  run.coupling().write_state(cp);
  std::vector<double> series;
  for (const auto& row : rows) series.insert(series.end(), row.begin(), row.end());
  cp.put("series", series);
  m.write_state(cp);
  cp.meta()["case_type"] = m.case_type();
  cp.meta()["step"] = run.coupling().steps();
  cp.meta()["ranks"] = ranks_of(run.comm());
  cp.meta()["first_plane"] = run.grid().first_plane();
  cp.write(restart.dir, restart.rank);
}

std::vector<std::vector<double>> read_checkpoint(CfdDemSolvers& run, CfdDemMeasurement& m, const CfdDemRestart& restart) {
  const int ranks = ranks_of(run.comm());
  if (!hs::common::Checkpoint::exists(restart.dir, restart.rank) && hs::common::Checkpoint::exists(restart.dir, 0)) {
    throw hs::common::ConfigError(fmt::format("{}: this checkpoint has no file for rank {}; it was written on fewer "
                                              "ranks (see rank 0's message)", restart.dir.string(), restart.rank));
  }
  const hs::common::Checkpoint cp = hs::common::Checkpoint::read(restart.dir, restart.rank);
  if (cp.meta().value("case_type", "") != m.case_type()) {
    throw hs::common::ConfigError(fmt::format("{}: not a {} checkpoint", restart.dir.string(), m.case_type()));
  }
  // Each rank saved its slab: the run resumes on as many ranks as wrote it (one file each, same slabs).
  const int saved_ranks = cp.meta().value("ranks", 1);
  if (saved_ranks != ranks || cp.meta().value("first_plane", 0) != run.grid().first_plane()) {
    throw hs::common::ConfigError(fmt::format("{}: checkpoint written on {} MPI rank(s), this run has {}; resume with "
                                              "mpirun -np {} (a run's slabs cannot be redistributed)",
                                              restart.dir.string(), saved_ranks, ranks, saved_ranks));
  }
  run.coupling().read_state(cp);
  const std::vector<double>& series = cp.doubles("series");
  const std::size_t width = m.columns().size();
  if (series.size() != width * static_cast<std::size_t>(run.coupling().steps())) {
    throw hs::common::ConfigError(fmt::format("{}: checkpoint series of {} values for {} steps", restart.dir.string(),
                                              series.size(), run.coupling().steps()));
  }
  m.read_state(cp);
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < series.size(); k += width) {
    rows.emplace_back(series.begin() + static_cast<long>(k), series.begin() + static_cast<long>(k + width));
  }
  return rows;
}

/// Whether any rank says yes: a checkpoint or a stop is decided by all ranks together, so that every slab's file
/// holds the same step (each rank's wall clock and signals are its own).
bool on_any_rank(bool mine, MPI_Comm comm) {
  int any = mine ? 1 : 0;
  if (ranks_of(comm) > 1) MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, comm);
  return any != 0;
}

/// The groups every CFD-DEM run has: n_coupling and the viscous number nu dt / dx^2 (PISO's stability measure,
/// fvm_solver.hpp).
nlohmann::json skeleton_groups(const CfdDemSolvers& run) {
  const FvmSolver& f = run.fluid();
  return {{"n_coupling", run.coupling_settings().n_coupling},
          {"viscous_number", f.fluid().kinematic_viscosity_m2_s * f.settings().dt_s / std::pow(f.grid().dx_m(), 2)}};
}

}  // namespace

CfdDemSolvers::CfdDemSolvers(CfdDemSetup setup, MPI_Comm comm)
    : shape_(std::move(setup.shape)), comm_(comm), coupling_settings_(setup.coupling) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (ranks > 1) {
    const bool periodic_z = setup.grid.sides[4].type == SideType::periodic;
    decomposition_ = std::make_unique<hs::common::CartesianDecomposition>(
        hs::common::DecompositionSpec{.global_nodes = FvmGrid::cells_of(setup.grid), .periodic = {false, false, periodic_z},
                                      .ranks_per_axis = {1, 1, 0}, .ghost = 2},
        comm);
    dem_slabs_ = std::make_unique<DemSlabs>(*decomposition_, setup.dem.domain, setup.grid.dx_m);
  }
  grid_ = std::make_unique<FvmGrid>(*shape_, setup.grid, decomposition_.get());
  dem_ = std::make_unique<DemSystem>(setup.dem, shape_.get(), dem_slabs_.get());
  fluid_ = std::make_unique<FvmSolver>(*grid_, setup.fluid, setup.piso, setup.drive, comm);
  coupling_ = std::make_unique<CfdDemCoupling>(*fluid_, *dem_, setup.coupling, std::move(setup.closures));
}

CfdDemOutcome run_cfd_dem(CfdDemSolvers& run, CfdDemMeasurement& m, const CfdDemLoopOptions& options) {
  const CfdDemRestart& restart = options.restart;
  CfdDemCoupling& coupling = run.coupling();
  CfdDemOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  m.prepare(run);
  out.prepare_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto show = [&](const std::vector<double>& row) {
    if (options.on_row) options.on_row(row);
    if (options.progress != nullptr) options.progress->update(static_cast<long>(out.rows.size()));
  };
  if (restart.resume) {
    out.rows = read_checkpoint(run, m, restart);   // restores the mean velocity the saved run used for u_r+ too
    for (const auto& row : out.rows) {
      if (options.on_row) options.on_row(row);
    }
    // One update for the saved rows, so the ETA is measured from the restart, not over the replay's instant.
    if (options.progress != nullptr && !out.rows.empty()) options.progress->update(static_cast<long>(out.rows.size()));
  } else {
    m.start(run);
  }
  hs::common::TimeLoop loop(options.steps, coupling.steps());
  loop.add("dem_substeps", [&] { coupling.dem_substeps(); });
  m.add_stages(loop, run);
  loop.add("particles_to_grid", [&] { coupling.particles_to_grid(); });
  loop.add("fluid_step", [&] { coupling.fluid_step(); });
  loop.add("fluid_to_particles", [&] { coupling.fluid_to_particles(); });
  bool finished = false;
  loop.add("measure", [&] {
    out.rows.push_back(m.sample(run));
    finished = m.finished(out.rows);
  });
  if (options.after_step) {
    loop.add("output_frames", [&] { options.after_step(run, coupling.steps(), finished || coupling.steps() == options.steps); });
  }
  hs::common::CheckpointSchedule schedule(options.checkpoint_every_wall_s);
  const hs::common::StopRequestScope stop_requests;
  while (!finished && loop.step() < loop.end_step()) {
    loop.run_steps(1);
    show(out.rows.back());
    int signal = hs::common::stop_signal();
    if (ranks_of(run.comm()) > 1) MPI_Allreduce(MPI_IN_PLACE, &signal, 1, MPI_INT, MPI_MAX, run.comm());
    if (signal != 0) {
      if (!restart.dir.empty()) write_checkpoint(run, m, out.rows, restart);
      throw hs::common::RunInterrupted(fmt::format("stopped by signal {} at step {} of {}{}", signal, coupling.steps(),
                                                   options.steps,
                                                   restart.dir.empty() ? "" : "; checkpoint written, continue with --resume"),
                                       signal);
    }
    if (!restart.dir.empty() && on_any_rank(schedule.due(), run.comm())) write_checkpoint(run, m, out.rows, restart);
  }
  if (!restart.dir.empty()) write_checkpoint(run, m, out.rows, restart);
  out.summary = m.summary(run, out.rows);
  const nlohmann::json groups = skeleton_groups(run);
  for (const auto& g : groups.items()) out.summary["groups"][g.key()] = g.value();
  out.summary["numerics"]["cfd_steps"] = static_cast<long>(out.rows.size());
  out.summary["numerics"]["prepare_seconds"] = out.prepare_seconds;
  // The pressure solve's AMG hierarchy: built anew or kept for a step's new matrix (since the start or the resume).
  out.summary["numerics"]["pressure_amg_setups"] = run.fluid().pressure_solver().setups();
  out.summary["numerics"]["pressure_amg_reuses"] = run.fluid().pressure_solver().reuses();
  out.summary["timings"] = loop.timings();
  out.timing_table = loop.timing_table();
  return out;
}

}  // namespace hs::unresolved
