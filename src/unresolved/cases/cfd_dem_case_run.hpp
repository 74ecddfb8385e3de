// SPDX-License-Identifier: MIT
// `hemoscale run` for a case on the CFD-DEM skeleton: run folder outputs (timeseries.csv, ParaView frames),
// progress with ETA, the stage timings in the log, summary.json with the case's checks.
#pragma once

#include <string>

#include "common/check_list.hpp"
#include "common/run_context.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"

namespace hs::unresolved {

struct CfdDemFolderOptions {
  long steps = 1;
  double checkpoint_every_wall_s = 600.0;
  double vtk_every_s = 0.0;   // [output] vtk_every_s; 0: the final frame only
};

/// Runs `m` in ctx's folder: timeseries.csv with the measurement's columns (rank 0; a resumed run rewrites it from
/// the checkpoint's rows), progress + ETA, particles.pvd/fields.pvd frames (cfd_dem_frames.hpp), checkpoints in
/// checkpoint/ (resumed with --resume), and the table of wall seconds per stage in the log.
[[nodiscard]] CfdDemOutcome run_cfd_dem_in_folder(hs::common::RunContext& ctx, CfdDemSolvers& run, CfdDemMeasurement& m,
                                                  const CfdDemFolderOptions& options);

/// Writes summary.json with the checks' verdicts, prints the checks (rank 0) and returns the exit code.
int finish_cfd_dem_case(hs::common::RunContext& ctx, nlohmann::json summary, const hs::common::CheckList& checks,
                        const std::string& case_type);

}  // namespace hs::unresolved
