// SPDX-License-Identifier: MIT
// `hemoscale run` for case type "tube-pries": the skeleton's run folder and outputs, then the Pries 1992 comparison
// and the case's checks (here, on the validation side, because they read analysis/). Runs on any number of MPI
// ranks (z-slabs of the tube, docs/cfd-dem.md "Distributed CFD-DEM").
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/log.hpp"
#include "common/run_context.hpp"
#include "unresolved/cases/cfd_dem_case_run.hpp"
#include "unresolved/cases/grid_budget.hpp"
#include "unresolved/cases/tube_pries.hpp"
#include "unresolved/cases/tube_pries_measurement.hpp"
#include "validate/tube_pries_checks.hpp"
#include "validate/tube_pries_comparison.hpp"

namespace hs::unresolved {

int run_tube_pries(const hs::common::CaseRequest& request) {
  const TubePriesConfig c = parse_tube_pries(*request.config, request.quick);
  const double tube_volume_m3 = std::numbers::pi * 0.25 * c.diameter_m * c.diameter_m * c.length_m;
  require_tube_grid_memory(*request.config, c.diameter_m, c.length_m, c.cells_across,
                           c.tube_hematocrit * tube_volume_m3 / c.particles.volume_m3());
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "tube-pries");
  hs::common::Log& log = ctx.log();
  log.set_quiet(request.quiet);
  log.info("tube-pries: D = {:.4g} m, L = {:.4g} m, Ht_c = {:.3g}, {} cells across, dt = {:.4g} s, n_coupling = {}, wall correction {}",
           c.diameter_m, c.length_m, c.tube_hematocrit, c.cells_across, c.dt_s, c.n_coupling,
           hs::closures::wall_correction_name(c.wall_correction));
  if (c.max_end_time_s > c.end_time_s) {
    log.info("tube-pries: {:.4g} s, then on until Ht_d and mu_rel are steady (trends within {:.3g} % over the averaging "
             "window at two checks {:.4g} s apart), at most {:.4g} s", c.end_time_s, 100.0 * c.steady_tolerance,
             static_cast<double>(steady_check_every_steps(c)) * c.dt_s, c.max_end_time_s);
  }
  if (ctx.ranks() > 1) log.info("tube-pries: the grid and the cells on {} z-slabs, one per MPI rank", ctx.ranks());
  CfdDemSolvers run(tube_pries_setup(c), MPI_COMM_WORLD);
  TubePriesMeasurement m(c);
  const CfdDemOutcome out = run_cfd_dem_in_folder(ctx, run, m,
                                                  {.steps = max_steps_of(c),
                                                   .checkpoint_every_wall_s = c.checkpoint_every_wall_s,
                                                   .vtk_every_s = c.vtk_every_s});
  TubePriesResult r = tube_pries_result(out.summary);
  add_pries_comparison(c, r);
  hs::common::CheckList checks;
  check_tube_pries(c, r, {.quick = request.quick}, checks);
  log.result("Ht_d = {:.4f} (Pries {:.4f}, {:+.1f}%), mu_rel = {:.4f} (Pries {:.4f}, {:+.1f}%){}; outputs in {}", r.ht_d,
             r.ht_d_pries, r.ht_d_error_pct, r.mu_rel, r.mu_rel_pries, r.mu_rel_error_pct,
             request.quick ? " (--quick: not a comparison, the run is far from steady)" : "", ctx.folder().path().string());
  return finish_cfd_dem_case(ctx, r.summary, checks, "tube-pries");
}

}  // namespace hs::unresolved
