// SPDX-License-Identifier: MIT
// `hemoscale run` for case type "tube-pries": run folder, time series, summary.json and the log line.
#include <fmt/format.h>

#include "common/io/csv_writer.hpp"
#include "common/log.hpp"
#include "common/progress.hpp"
#include "common/run_context.hpp"
#include "common/run_folder.hpp"
#include "unresolved/cases/cfd_dem_frames.hpp"
#include "unresolved/cases/tube_pries.hpp"
#include "unresolved/cases/tube_pries_checks.hpp"
#include "unresolved/coupling/one_rank_guard.hpp"

namespace hs::unresolved {

int run_tube_pries(const hs::common::CaseRequest& request) {
  require_one_rank("tube-pries");   // before the run folder is made
  const TubePriesConfig c = parse_tube_pries(*request.config, request.quick);
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "tube-pries");
  hs::common::Log& log = ctx.log();
  log.set_quiet(request.quiet);
  log.info("tube-pries: D = {:.4g} m, L = {:.4g} m, Ht_c = {:.3g}, {} cells across, dt = {:.4g} s, n_coupling = {}, wall correction {}",
           c.diameter_m, c.length_m, c.tube_hematocrit, c.cells_across, c.dt_s, c.n_coupling,
           hs::closures::wall_correction_name(c.wall_correction));
  hs::common::CsvWriter series(ctx.folder().file("timeseries.csv"),
                               {"time_s", "flow_rate_blood_m3_s", "flow_rate_rbc_m3_s", "discharge_hematocrit", "pressure_iterations"});
  const long steps = std::max(1L, std::lround(c.end_time_s / c.dt_s));
  hs::common::Progress progress("tube-pries", steps, ctx.show_progress());
  long done = 0;
  // Checkpoints every checkpoint_every_wall_s and at the end; --resume replays the saved samples into a fresh
  // timeseries.csv, then continues (tube_cell.cpp's pattern).
  const TubePriesRestart restart{.dir = ctx.folder().checkpoint_dir(), .resume = ctx.resuming(), .rank = ctx.rank()};
  // ParaView output, rank 0 only: particles.pvd + fields.pvd with vtk/ frames named by CFD step.
  CfdDemFrames frames(ctx.rank() == 0 ? ctx.folder().path() : std::filesystem::path{}, c.vtk_every_s);
  if (ctx.resuming()) log.info("resuming from the checkpoint in {}", restart.dir.string());
  const TubePriesResult r = simulate_tube_pries(c, [&](const TubePriesSample& s) {
    series.row({s.time_s, s.q_blood_m3_s, s.q_rbc_m3_s, s.ht_d, s.pressure_iterations});
    progress.update(++done);
  }, restart, &frames);
  progress.finish();
  hs::common::CheckList checks;
  check_tube_pries(c, r, {.quick = request.quick}, checks);
  nlohmann::json summary = r.summary;
  checks.write_to(summary);
  ctx.write_summary(summary);
  log.info("Ht_d = {:.4f} (Pries {:.4f}, {:+.1f}%), mu_rel = {:.4f} (Pries {:.4f}, {:+.1f}%){}; outputs in {}", r.ht_d,
           r.ht_d_pries, r.ht_d_error_pct, r.mu_rel, r.mu_rel_pries, r.mu_rel_error_pct,
           request.quick ? " (--quick: not a comparison, the run is far from steady)" : "", ctx.folder().path().string());
  if (ctx.rank() == 0) checks.print("tube-pries");
  return checks.exit_code();
}

}  // namespace hs::unresolved
