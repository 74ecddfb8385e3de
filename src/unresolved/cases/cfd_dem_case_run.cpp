// SPDX-License-Identifier: MIT
// `hemoscale run` around the CFD-DEM skeleton: outputs, progress, timings, summary.
#include "unresolved/cases/cfd_dem_case_run.hpp"

#include <memory>
#include <utility>

#include "common/io/csv_writer.hpp"
#include "common/progress.hpp"
#include "unresolved/cases/cfd_dem_frames.hpp"

namespace hs::unresolved {

CfdDemOutcome run_cfd_dem_in_folder(hs::common::RunContext& ctx, CfdDemSolvers& run, CfdDemMeasurement& m,
                                    const CfdDemFolderOptions& options) {
  std::unique_ptr<hs::common::CsvWriter> series;
  if (ctx.rank() == 0) series = std::make_unique<hs::common::CsvWriter>(ctx.folder().file("timeseries.csv"), m.columns());
  hs::common::Progress progress(m.case_type(), options.steps, ctx.show_progress());
  // ParaView output, written by rank 0: particles.pvd + fields.pvd with vtk/ frames named by CFD step.
  CfdDemFrames frames(ctx.rank() == 0 ? ctx.folder().path() : std::filesystem::path{}, options.vtk_every_s);
  if (ctx.resuming()) ctx.log().info("resuming from the checkpoint in {}", ctx.folder().checkpoint_dir().string());
  const CfdDemOutcome out = run_cfd_dem(
      run, m,
      {.steps = options.steps,
       .checkpoint_every_wall_s = options.checkpoint_every_wall_s,
       .restart = {.dir = ctx.folder().checkpoint_dir(), .resume = ctx.resuming(), .rank = ctx.rank()},
       .on_row = [&](const std::vector<double>& row) {
         if (series) series->row(row);
       },
       .after_step = [&](const CfdDemSolvers& s, long step, bool last) { frames.after_step(s, step, last); },
       .progress = &progress});
  progress.finish();
  ctx.log().info("{}: {:.3f} s before the loop (the case's prepare), wall seconds per stage of the CFD-DEM step:\n{}",
                 m.case_type(), out.prepare_seconds, out.timing_table);
  return out;
}

int finish_cfd_dem_case(hs::common::RunContext& ctx, nlohmann::json summary, const hs::common::CheckList& checks,
                        const std::string& case_type) {
  ctx.write_summary(std::move(summary), checks);
  checks.print(ctx.log(), case_type);   // rank 0 prints: the log writes result lines there only
  return checks.exit_code();
}

}  // namespace hs::unresolved
