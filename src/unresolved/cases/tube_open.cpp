// SPDX-License-Identifier: MIT
// Case type "tube-open": the case file, the open tube's solvers and the `hemoscale run` entry. Runs on any number of
// MPI ranks (z-slabs of the tube, docs/cfd-dem.md "Distributed CFD-DEM").
#include "unresolved/cases/tube_open.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/geometry/opening_condition.hpp"
#include "common/geometry/tube.hpp"
#include "common/run_context.hpp"
#include "unresolved/cases/cfd_dem_case_run.hpp"
#include "unresolved/cases/grid_budget.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/cases/open_geometry_measurement.hpp"
#include "unresolved/cases/step_limits.hpp"
#include "unresolved/dem/cell_injector.hpp"

namespace hs::unresolved {

long TubeOpenConfig::steps() const { return std::max(1L, std::lround(end_time_s / dt_s)); }

TubeOpenConfig parse_tube_open(hs::common::ConfigFile& file, bool quick) {
  auto root = file.root();
  auto geometry = root.section("geometry");
  auto flow = root.section("flow");
  auto cells = root.section("cells");
  auto particles = root.section_or_empty("particles");
  auto coupling = root.section_or_empty("coupling");
  auto numerics = root.section("numerics");
  TubeOpenConfig c{};
  c.diameter_m = geometry.positive("diameter_m");
  c.length_m = geometry.positive("length_m");
  c.fluid = hs::common::parse_fluid(root.section("fluid"));
  c.inlet_mean_velocity_m_s = flow.positive("inlet_mean_velocity_m_s");
  // Above 0 and at most CellInjector's sanity bound 0.6 (normal blood 0.37-0.53, cell_injector.hpp).
  c.discharge_hematocrit = cells.number_in("discharge_hematocrit", 1e-6, max_discharge_hematocrit);
  c.seed = static_cast<std::uint64_t>(cells.integer_in_or("seed", 0, 1L << 40, 1));
  c.particles = parse_particle_params(particles);
  c.model = parse_coupling_model(coupling, file.file().parent_path());
  c.cells_across = static_cast<int>(numerics.integer_in("cells_across_diameter", 4, 1000));
  read_loop_numerics(numerics, c);
  const double dx = c.diameter_m / c.cells_across;
  const double along = c.length_m / dx;
  if (std::abs(along - std::round(along)) > 1e-6 * along) {
    geometry.fail("length_m", fmt::format("must be a whole number of cells of {:.6g} m (it is {:.4f})", dx, along));
  }
  if (c.particles.diameter_m >= c.diameter_m) {
    geometry.fail("diameter_m", fmt::format("must be larger than a cell's sphere (d_p = {:.4g} m)", c.particles.diameter_m));
  }
  const double u_max = 2.0 * c.inlet_mean_velocity_m_s;   // the parabola's centreline speed
  check_courant(numerics, u_max, c.dt_s, dx, "the inlet's centreline speed");
  check_dem_step(numerics, c.particles, c.dt_s, c.n_coupling);
  if (c.model.self_induced_correction) {   // SelfMobility is measured in a periodic tube's frame
    coupling.fail("self_induced_correction", "is measured in a periodic tube (tube-pries); tube-open takes the closures' inputs "
                                             "from the channel frame: leave it out or set it to false");
  }
  c.quick = quick;
  if (quick) c.end_time_s = std::min(c.end_time_s, 20.0 * c.dt_s);
  c.vtk_every_s = root.section_or_empty("output").positive_or("vtk_every_s", 0.0);   // 0 (absent): final frame only
  file.finish();
  return c;
}

OpenGeometryConfig open_geometry_of(const TubeOpenConfig& c) {
  const double r = 0.5 * c.diameter_m;
  const hs::common::Opening inlet{.name = "inlet", .kind = hs::common::OpeningKind::inlet, .centre_m = {0, 0, 0},
                                  .normal = {0, 0, -1}, .radius_m = r};
  const hs::common::Opening outlet{.name = "outlet", .kind = hs::common::OpeningKind::outlet, .centre_m = {0, 0, c.length_m},
                                   .normal = {0, 0, 1}, .radius_m = r};
  OpenGeometryConfig g{};
  g.shape = std::make_shared<hs::common::Tube>(hs::common::TubeSpec{.start_m = {0, 0, 0}, .end_m = {0, 0, c.length_m}, .radius_m = r});
  g.box = {{-r, -r, 0.0}, {r, r, c.length_m}};
  g.openings = {hs::common::flow_rate_inlet(inlet, c.inlet_mean_velocity_m_s * std::numbers::pi * r * r),
                hs::common::pressure_outlet(outlet, 0.0)};
  g.discharge_hematocrit = {c.discharge_hematocrit, 0.0};
  g.fluid = c.fluid;
  g.seed = c.seed;
  g.particles = c.particles;
  g.model = c.model;
  g.dx_m = c.diameter_m / c.cells_across;
  g.dt_s = c.dt_s;
  g.piso_correctors = c.piso_correctors;
  g.pressure_coupling = c.pressure_coupling;
  g.n_coupling = c.n_coupling;
  g.end_time_s = c.end_time_s;
  g.average_from_fraction = c.average_from_fraction;
  g.checkpoint_every_wall_s = c.checkpoint_every_wall_s;
  g.vtk_every_s = c.vtk_every_s;
  g.quick = c.quick;
  return g;
}

CfdDemSetup tube_open_setup(const TubeOpenConfig& c) { return open_geometry_setup(open_geometry_of(c)); }

nlohmann::json simulate_tube_open(const TubeOpenConfig& c, const std::function<void(const std::vector<double>&)>& on_row,
                                  const CfdDemRestart& restart, MPI_Comm comm) {
  const OpenGeometryConfig g = open_geometry_of(c);
  CfdDemSolvers run(open_geometry_setup(g), comm);
  OpenGeometryMeasurement m(g, "tube-open");
  return run_cfd_dem(run, m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .restart = restart,
                              .on_row = on_row, .after_step = {}, .progress = nullptr})
      .summary;
}

void add_tube_summary(const TubeOpenConfig& c, nlohmann::json& summary) {
  nlohmann::json& s = summary["results"];
  const double ht_in = s["openings"][0]["discharge_hematocrit"].get<double>();    // "inlet", "outlet": names sorted
  const double ht_out = s["openings"][1]["discharge_hematocrit"].get<double>();
  const double ht_tube = s["domain_hematocrit"].get<double>();
  s["diameter_um"] = c.diameter_m * 1e6;
  s["length_um"] = c.length_m * 1e6;
  s["discharge_hematocrit_requested"] = c.discharge_hematocrit;
  s["transits"] = s["residence_times"];   // the tube's volume over its inflow: L / U
  s["discharge_hematocrit_inlet"] = ht_in;
  s["discharge_hematocrit_outlet"] = ht_out;
  s["outlet_vs_inlet_discharge_pct"] = ht_in > 0.0 ? 100.0 * (ht_out - ht_in) / ht_in : 0.0;
  s["tube_hematocrit"] = ht_tube;
  s["tube_over_discharge_hematocrit"] = ht_in > 0.0 ? ht_tube / ht_in : 0.0;   // < 1: the Fahraeus effect
}

void check_tube_open(const TubeOpenConfig& c, const nlohmann::json& s, hs::common::CheckList& checks) {
  check_open_geometry(open_geometry_of(c), s, checks);
  if (c.quick) return;   // open-geometry's checks said so
  // #21's acceptance: what goes in comes out (2%), and the tube hematocrit below the discharge one (Fahraeus).
  const double diff = s["outlet_vs_inlet_discharge_pct"].get<double>();
  checks.expect("outlet vs inlet discharge hematocrit", std::abs(diff) <= 2.0, fmt::format("{:+.2f}% (band +-2%)", diff));
  const double fahraeus = s["tube_over_discharge_hematocrit"].get<double>();
  checks.expect("Fahraeus: tube hematocrit below the inlet's discharge hematocrit", fahraeus < 1.0,
                fmt::format("Ht_T / Ht_d = {:.4f}", fahraeus));
}

int run_tube_open(const hs::common::CaseRequest& request) {
  const TubeOpenConfig c = parse_tube_open(*request.config, request.quick);
  const double tube_volume_m3 = std::numbers::pi * 0.25 * c.diameter_m * c.diameter_m * c.length_m;
  require_tube_grid_memory(*request.config, c.diameter_m, c.length_m, c.cells_across,
                           c.discharge_hematocrit * tube_volume_m3 / c.particles.volume_m3());
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "tube-open");
  ctx.log().set_quiet(request.quiet);
  ctx.log().info("tube-open: D = {:.4g} m, L = {:.4g} m, inlet U = {:.4g} m/s, Ht_d = {:.3g}, {} cells across, dt = {:.4g} s, "
                 "n_coupling = {}, {:.1f} transits", c.diameter_m, c.length_m, c.inlet_mean_velocity_m_s, c.discharge_hematocrit,
                 c.cells_across, c.dt_s, c.n_coupling, c.end_time_s / c.transit_time_s());
  if (ctx.ranks() > 1) ctx.log().info("tube-open: the grid and the cells on {} z-slabs, one per MPI rank", ctx.ranks());
  const OpenGeometryConfig g = open_geometry_of(c);
  CfdDemSolvers run(open_geometry_setup(g), MPI_COMM_WORLD);
  OpenGeometryMeasurement m(g, "tube-open");
  CfdDemOutcome out = run_cfd_dem_in_folder(
      ctx, run, m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .vtk_every_s = c.vtk_every_s});
  add_tube_summary(c, out.summary);
  hs::common::CheckList checks;
  const nlohmann::json& res = out.summary["results"];
  check_tube_open(c, res, checks);
  ctx.log().result("tube-open: Ht_d inlet {:.4f}, outlet {:.4f}, tube Ht_T {:.4f}; {} cells in, {} out, {} present; outputs in {}",
                   res["discharge_hematocrit_inlet"].get<double>(), res["discharge_hematocrit_outlet"].get<double>(),
                   res["tube_hematocrit"].get<double>(), res["cells_injected"].get<long>(), res["cells_removed"].get<long>(),
                   res["cells_present"].get<long>(), ctx.folder().path().string());
  return finish_cfd_dem_case(ctx, out.summary, checks, "tube-open");
}

}  // namespace hs::unresolved
