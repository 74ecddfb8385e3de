// SPDX-License-Identifier: MIT
// Case type "open-geometry": the case file, the solvers and the `hemoscale run` entry.
#include "unresolved/cases/open_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/geometry/openings_from_config.hpp"
#include "common/geometry/shape_from_config.hpp"
#include "common/geometry/turned_shape.hpp"
#include "common/run_context.hpp"
#include "unresolved/cases/bifurcation_study_measurement.hpp"
#include "unresolved/cases/cfd_dem_case_run.hpp"
#include "unresolved/cases/grid_budget.hpp"
#include "unresolved/cases/loop_numerics.hpp"
#include "unresolved/cases/open_geometry_measurement.hpp"
#include "unresolved/cases/step_limits.hpp"
#include "unresolved/cases/stenosis_study_measurement.hpp"
#include "unresolved/dem/cell_injector.hpp"

namespace hs::unresolved {
namespace {

using hs::common::OpeningFlowType;
using hs::common::Vec3;

hs::common::Box3 read_box(hs::common::ConfigSection domain, const hs::common::Shape& shape) {
  if (!domain.has("box_min_m") && !domain.has("box_max_m")) return shape.bounds();
  hs::common::Box3 box;
  for (const char* key : {"box_min_m", "box_max_m"}) {
    const auto v = domain.numbers_in(key, -1e300, 1e300, 3);
    if (v.size() != 3) domain.fail(key, "must have exactly 3 values [x, y, z] (m)");
    (std::string_view(key) == "box_min_m" ? box.lo : box.hi) = Vec3{v[0], v[1], v[2]};
  }
  for (int a = 0; a < 3; ++a) {
    if (!(box.hi[a] > box.lo[a])) domain.fail("box_max_m", "must exceed box_min_m along every axis");
  }
  return box;
}

/// The inlets' discharge hematocrit, read from their [openings.NAME] sections (the conditions are in the same order).
std::vector<double> read_hematocrits(hs::common::ConfigSection openings, const std::vector<hs::common::OpeningCondition>& conditions) {
  std::vector<double> ht;
  std::size_t k = 0;
  for (const std::string& name : openings.keys()) {
    hs::common::ConfigSection s = openings.section(name);
    if (conditions[k++].type == OpeningFlowType::flow_rate_inlet) {
      // Above 0 and at most CellInjector's sanity bound 0.6 (normal blood 0.37-0.53, cell_injector.hpp).
      ht.push_back(s.number_in("discharge_hematocrit", 1e-6, max_discharge_hematocrit));
    } else {
      if (s.has("discharge_hematocrit")) s.fail("discharge_hematocrit", "is for an inlet: an outlet passes what reaches it");
      ht.push_back(0.0);
    }
  }
  return ht;
}

/// With cells beside the openings the fluid's fluxes balance only through a pressure outlet (docs/openings.md).
void require_pressure_outlet(hs::common::ConfigSection openings, const std::vector<hs::common::OpeningCondition>& conditions) {
  const auto names = openings.keys();
  std::string last_outlet;
  for (std::size_t k = 0; k < conditions.size(); ++k) {
    if (conditions[k].type == OpeningFlowType::pressure_outlet) return;
    if (conditions[k].type == OpeningFlowType::flow_fraction_outlet) last_outlet = names[k];
  }
  const char* why = "a CFD-DEM run needs at least one outlet with pressure_Pa (Pa): with cells beside the openings the "
                    "fluid's fluxes balance only through a pressure outlet (docs/openings.md)";
  if (last_outlet.empty()) openings.fail(names.front(), fmt::format("there is no outlet; {}", why));
  openings.section(last_outlet).fail("flow_fraction", why);
}

/// The case's measurement; with [study] the bifurcation or stenosis study's on top of it (*_study_measurement.hpp).
std::unique_ptr<CfdDemMeasurement> make_measurement(const OpenGeometryConfig& c) {
  if (c.stenosis_study) return std::make_unique<StenosisStudyMeasurement>(c, *c.stenosis_study);
  if (c.study) return std::make_unique<BifurcationStudyMeasurement>(c, *c.study);
  return std::make_unique<OpenGeometryMeasurement>(c);
}

}  // namespace

long OpenGeometryConfig::steps() const { return std::max(1L, std::lround(end_time_s / dt_s)); }

double OpenGeometryConfig::inflow_m3_s() const {
  double q = 0.0;
  for (const auto& o : openings) q += o.type == OpeningFlowType::flow_rate_inlet ? o.flow_rate_m3_s : 0.0;
  return q;
}

OpenGeometryConfig parse_open_geometry(hs::common::ConfigFile& file, bool quick) {
  auto root = file.root();
  auto numerics = root.section("numerics");
  auto coupling = root.section_or_empty("coupling");
  OpenGeometryConfig c{};
  c.shape = hs::common::shape_from_config(root.section("geometry"));
  c.box = read_box(root.section_or_empty("domain"), *c.shape);
  auto openings = root.section("openings");
  c.openings = hs::common::opening_conditions_from_config(openings, *c.shape, c.box);
  require_pressure_outlet(openings, c.openings);
  c.discharge_hematocrit = read_hematocrits(openings, c.openings);
  c.fluid = hs::common::parse_fluid(root.section("fluid"));
  c.seed = static_cast<std::uint64_t>(root.section_or_empty("cells").integer_in_or("seed", 0, 1L << 40, 1));
  auto particles = root.section_or_empty("particles");
  c.particles = parse_particle_params(particles);
  c.model = parse_coupling_model(coupling, file.file().parent_path());
  if (c.model.self_induced_correction) {   // SelfMobility is measured in a periodic tube's frame
    coupling.fail("self_induced_correction", "is measured in a periodic tube (tube-pries); an open geometry takes the "
                                             "closures' inputs from the channel frame: leave it out or set it to false");
  }
  c.dx_m = numerics.positive("dx_m");
  read_loop_numerics(numerics, c);
  for (const auto& o : c.openings) {   // the developed parabola's centreline speed, 2 Q / (pi R^2)
    if (o.type != OpeningFlowType::flow_rate_inlet) continue;
    const double r = o.opening.radius_m;
    check_courant(numerics, 2.0 * o.flow_rate_m3_s / (std::numbers::pi * r * r), c.dt_s, c.dx_m,
                  fmt::format("the centreline speed of inlet '{}'", o.opening.name));
  }
  check_dem_step(numerics, c.particles, c.dt_s, c.n_coupling);
  c.quick = quick;
  if (quick) c.end_time_s = std::min(c.end_time_s, 20.0 * c.dt_s);
  c.vtk_every_s = root.section_or_empty("output").positive_or("vtk_every_s", 0.0);   // 0 (absent): final frame only
  // A run that claims a scale (the studies' paper-scale runs) fails when fewer cells passed through the device.
  c.min_cells_passed = root.section_or_empty("check").integer_in_or("min_cells_passed", 0, 1L << 40, 0);
  if (root.has("study") && dynamic_cast<const hs::common::TurnedToZ*>(c.shape.get()) != nullptr) {
    root.section("geometry").fail("axis", "the stenosis and bifurcation studies measure along x: with a [study] section "
                                          "leave axis out (or \"x\")");
  }
  if (dynamic_cast<const hs::common::StenosedTube*>(c.shape.get()) != nullptr) {
    c.stenosis_study = parse_stenosis_study(root, *c.shape);
  } else {
    c.study = parse_bifurcation_study(root, *c.shape);
  }
  file.finish();
  return c;
}

CfdDemSetup open_geometry_setup(const OpenGeometryConfig& c) {
  FvmGridSpec grid{.box_m = c.box, .dx_m = c.dx_m, .sides = {}};   // walls but for the openings
  grid.openings = c.openings;
  return {.shape = c.shape,
          .grid = grid,
          .fluid = c.fluid,
          .piso = {.dt_s = c.dt_s, .correctors = c.piso_correctors, .coupling = c.pressure_coupling},
          .drive = {},
          .dem = {.params = c.particles, .domain = {.box = c.box, .periodic = {false, false, false}}, .time_step_s = c.dt_s / c.n_coupling},
          .coupling = {.n_coupling = c.n_coupling, .void_fraction_rate = c.model.void_fraction_rate,
                       .closure_frame = ClosureFrame::channel, .wall_correction = c.model.wall_correction,
                       .suspension_viscosity = c.model.suspension_viscosity,
                       .smoothing_length_m = c.model.smoothing_length_m,
                       .buoyancy_over_footprint = c.model.buoyancy_over_footprint},
          .closures = make_closures(c.model)};
}

nlohmann::json simulate_open_geometry(const OpenGeometryConfig& c, const std::function<void(const std::vector<double>&)>& on_row,
                                      const CfdDemRestart& restart) {
  CfdDemSolvers run(open_geometry_setup(c));
  const auto m = make_measurement(c);
  return run_cfd_dem(run, *m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .restart = restart,
                              .on_row = on_row, .after_step = {}, .progress = nullptr})
      .summary;
}

namespace {

/// What open-geometry cannot do on several ranks, refused before the run folder is made: the studies' measurements
/// run on one rank, and on z-slabs the cells enter on the slab holding an inlet, so every inlet must face along z.
void require_slab_ready(const OpenGeometryConfig& c, const std::filesystem::path& file) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (ranks == 1) return;
  if (c.study || c.stenosis_study) {
    throw hs::common::ConfigError(fmt::format(
        "{}: [study]: the stenosis and bifurcation studies' measurements run on one rank only, and this run was started "
        "on {} MPI ranks: run it without mpirun (or mpirun -np 1), or leave out [study]", file.string(), ranks));
  }
  for (const auto& o : c.openings) {
    const hs::common::Vec3& n = o.opening.normal;
    if (o.type != OpeningFlowType::flow_rate_inlet || std::abs(std::abs(n.z) - 1.0) < 1e-12) continue;
    throw hs::common::ConfigError(fmt::format(
        "{}: [openings.{}]: on {} MPI ranks the grid is cut into z-slabs and cells enter on the slab holding their inlet, "
        "so an inlet must face along z (its normal is ({:.3g}, {:.3g}, {:.3g})): give [geometry] axis = \"z\" (the "
        "shape's +x along +z) with the openings in that frame, or run on one rank", file.string(), o.opening.name, ranks,
        n.x, n.y, n.z));
  }
}

}  // namespace

int run_open_geometry(const hs::common::CaseRequest& request) {
  const OpenGeometryConfig c = parse_open_geometry(*request.config, request.quick);
  require_slab_ready(c, request.config->file());   // before the run folder is made
  double max_ht = 0.0;   // an upper bound of the cells present: the box full at the highest inlet hematocrit
  for (const double h : c.discharge_hematocrit) max_ht = std::max(max_ht, h);
  const hs::common::Vec3 side = c.box.hi - c.box.lo;
  require_box_grid_memory(*request.config, c.box, c.dx_m, max_ht * side[0] * side[1] * side[2] / c.particles.volume_m3());
  hs::common::RunContext ctx = hs::common::RunContext::start(request, "open-geometry");
  ctx.log().set_quiet(request.quiet);
  ctx.log().info("open-geometry: {} openings, inflow {:.4g} m^3/s, dx = {:.4g} m, dt = {:.4g} s, n_coupling = {}, {} steps",
                 c.openings.size(), c.inflow_m3_s(), c.dx_m, c.dt_s, c.n_coupling, c.steps());
  if (ctx.ranks() > 1) ctx.log().info("open-geometry: the grid and the cells on {} z-slabs, one per MPI rank", ctx.ranks());
  CfdDemSolvers run(open_geometry_setup(c), MPI_COMM_WORLD);
  const auto m = make_measurement(c);
  const CfdDemOutcome out = run_cfd_dem_in_folder(
      ctx, run, *m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .vtk_every_s = c.vtk_every_s});
  hs::common::CheckList checks;
  const nlohmann::json& res = out.summary["results"];
  check_open_geometry(c, res, checks);
  ctx.log().result("open-geometry: {} cells in, {} out, {} present; domain hematocrit {:.4f}, mean DI {:.4f}; outputs in {}",
                   res["cells_injected"].get<long>(), res["cells_removed"].get<long>(), res["cells_present"].get<long>(),
                   res["domain_hematocrit"].get<double>(), res["mean_di"].get<double>(), ctx.folder().path().string());
  return finish_cfd_dem_case(ctx, out.summary, checks, "open-geometry");
}

}  // namespace hs::unresolved
