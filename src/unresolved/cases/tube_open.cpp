// SPDX-License-Identifier: MIT
// Case type "tube-open": the case file, the open tube's solvers and the `hemoscale run` entry.
#include "unresolved/cases/tube_open.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/run_context.hpp"
#include "unresolved/cases/cfd_dem_case_run.hpp"
#include "unresolved/cases/grid_budget.hpp"
#include "unresolved/cases/tube_open_measurement.hpp"
#include "unresolved/coupling/one_rank_guard.hpp"
#include "unresolved/dem/cell_injector.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"

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
  c.dt_s = numerics.positive("dt_s");
  // 4, not the FVM's 2: at the viscous number nu dt / dx^2 = 60 two PISO correctors let an odd-even mode grow in the
  // open tube and four settle it (measured, tests/unresolved/fvm/open_tube_test.cpp).
  c.piso_correctors = static_cast<int>(numerics.integer_in_or("piso_correctors", 1, 20, 4));
  c.pressure_coupling = pressure_coupling_from_name(numerics.one_of_or("pressure_coupling", {"piso", "projection"}, "piso"));
  c.n_coupling = static_cast<int>(numerics.integer_in("n_coupling", 1, 1000000));
  c.end_time_s = numerics.positive("end_time_s");
  c.average_from_fraction = numerics.number_in_or("average_from_fraction", 0.0, 0.95, 0.5);
  c.checkpoint_every_wall_s = numerics.positive_or("checkpoint_every_wall_s", 600.0);   // DESIGN.md: every N minutes
  const double dx = c.diameter_m / c.cells_across;
  const double along = c.length_m / dx;
  if (std::abs(along - std::round(along)) > 1e-6 * along) {
    geometry.fail("length_m", fmt::format("must be a whole number of cells of {:.6g} m (it is {:.4f})", dx, along));
  }
  if (c.particles.diameter_m >= c.diameter_m) {
    geometry.fail("diameter_m", fmt::format("must be larger than a cell's sphere (d_p = {:.4g} m)", c.particles.diameter_m));
  }
  const double u_max = 2.0 * c.inlet_mean_velocity_m_s;   // the parabola's centreline speed
  if (u_max * c.dt_s / dx > 1.0) {   // CFDEM keeps Co < 1 (methods note sec. 0)
    numerics.fail("dt_s", fmt::format("gives a Courant number {:.3g} > 1 at the inlet's centreline speed {:.4g} m/s; use "
                                      "dt_s <= {:.4g}", u_max * c.dt_s / dx, u_max, dx / u_max));
  }
  const double dt_dem = c.dt_s / c.n_coupling;
  const double limit = 0.1 * std::min(rayleigh_time_s(c.particles), hertz_time_s(c.particles, c.particles.max_impact_velocity_m_s));
  if (dt_dem > limit) {
    numerics.fail("n_coupling", fmt::format("gives a DEM step dt_s / n_coupling = {:.4g} s > 0.1 min(t_Rayleigh, t_Hertz) = "
                                            "{:.4g} s; use n_coupling >= {}", dt_dem, limit, static_cast<long>(std::ceil(c.dt_s / limit))));
  }
  if (c.model.self_induced_correction && c.particles.diameter_m > dx) {
    coupling.fail("self_induced_correction", fmt::format("needs spheres no larger than a cell, but d_p = {:.4g} m > dx = {:.4g} m",
                                                         c.particles.diameter_m, dx));
  }
  c.quick = quick;
  if (quick) c.end_time_s = std::min(c.end_time_s, 20.0 * c.dt_s);
  c.vtk_every_s = root.section_or_empty("output").positive_or("vtk_every_s", 0.0);   // 0 (absent): final frame only
  file.finish();
  return c;
}

CfdDemSetup tube_open_setup(const TubeOpenConfig& c) {
  const double r = 0.5 * c.diameter_m;
  const double u = c.inlet_mean_velocity_m_s;
  std::array<SideCondition, 6> sides{};   // x and y: walls (the tube's wall lies inside the box)
  sides[4].type = SideType::velocity_inlet;
  sides[4].inlet_velocity_m_s = [r, u](const hs::common::Vec3& x) {
    return hs::common::Vec3{0.0, 0.0, 2.0 * u * std::max(0.0, 1.0 - (x.x * x.x + x.y * x.y) / (r * r))};
  };
  sides[5].type = SideType::pressure_outlet;
  const hs::common::Box3 box{{-r, -r, 0.0}, {r, r, c.length_m}};
  return {.shape = std::make_unique<hs::common::Tube>(hs::common::TubeSpec{.start_m = {0, 0, 0}, .end_m = {0, 0, c.length_m},
                                                                            .radius_m = r}),
          .grid = {.box_m = box, .dx_m = c.diameter_m / c.cells_across, .sides = sides},
          .fluid = c.fluid,
          .piso = {.dt_s = c.dt_s, .correctors = c.piso_correctors, .coupling = c.pressure_coupling},
          .drive = {},
          .dem = {.params = c.particles, .domain = {.box = box, .periodic = {false, false, false}}, .time_step_s = c.dt_s / c.n_coupling},
          // The straight tube's frame is exact for the closures' inputs (radial lift direction, gamma+ from R).
          .coupling = {.n_coupling = c.n_coupling, .void_fraction_rate = c.model.void_fraction_rate, .axis = 2,
                       .axis_point_m = {0, 0, 0}, .tube_radius_m = r, .wall_correction = c.model.wall_correction,
                       .self_induced_correction = c.model.self_induced_correction,
                       .suspension_viscosity = c.model.suspension_viscosity},
          .closures = make_closures(c.model)};
}

nlohmann::json simulate_tube_open(const TubeOpenConfig& c, const std::function<void(const std::vector<double>&)>& on_row,
                                  const CfdDemRestart& restart) {
  CfdDemSolvers run(tube_open_setup(c));
  TubeOpenMeasurement m(c);
  return run_cfd_dem(run, m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .restart = restart,
                              .on_row = on_row, .after_step = {}, .progress = nullptr})
      .summary;
}

int run_tube_open(const hs::common::CaseRequest& request) {
  require_one_rank("tube-open");   // before the run folder is made
  const TubeOpenConfig c = parse_tube_open(*request.config, request.quick);
  const double tube_volume_m3 = std::numbers::pi * 0.25 * c.diameter_m * c.diameter_m * c.length_m;
  require_tube_grid_memory(*request.config, c.diameter_m, c.length_m, c.cells_across,
                           c.discharge_hematocrit * tube_volume_m3 / c.particles.volume_m3());
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "tube-open");
  ctx.log().set_quiet(request.quiet);
  ctx.log().info("tube-open: D = {:.4g} m, L = {:.4g} m, inlet U = {:.4g} m/s, Ht_d = {:.3g}, {} cells across, dt = {:.4g} s, "
                 "n_coupling = {}, {:.1f} transits", c.diameter_m, c.length_m, c.inlet_mean_velocity_m_s, c.discharge_hematocrit,
                 c.cells_across, c.dt_s, c.n_coupling, c.end_time_s / c.transit_time_s());
  CfdDemSolvers run(tube_open_setup(c));
  TubeOpenMeasurement m(c);
  const CfdDemOutcome out = run_cfd_dem_in_folder(
      ctx, run, m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .vtk_every_s = c.vtk_every_s});
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
