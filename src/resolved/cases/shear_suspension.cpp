// SPDX-License-Identifier: MIT
// Many cells in simple shear between moving plates: the suspension's relative viscosity from the cells' stresslets.
#include "resolved/cases/shear_suspension.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include <fmt/format.h>
#include <mpi.h>

#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "common/io/vtk_polydata.hpp"
#include "common/progress.hpp"
#include "common/run_context.hpp"
#include "common/time_loop.hpp"
#include "resolved/cases/cell_placement.hpp"
#include "resolved/cases/cell_simulation.hpp"
#include "resolved/cases/lattice_budget.hpp"
#include "resolved/cases/shear_suspension_config.hpp"
#include "resolved/cases/shear_suspension_series.hpp"
#include "resolved/ibm/cell_suspension.hpp"
#include "resolved/measure/cell_shape.hpp"
#include "resolved/measure/stresslet.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

/// Clearance (in dx) between a released cell and a plate: the 4-point IBM stencil reaches 2 dx (as the shear case).
constexpr double kWallClearanceDx = 2.0;
/// The contact springs are explicit: k h^2 / m_vertex < 4 is symplectic Euler's bound, 1 keeps a margin for several
/// vertices in contact at once (as the stenosis case's wall repulsion).
constexpr double kContactStabilityMax = 1.0;
/// How far the closest-approach search looks (the contact range or this, the larger): pairs beyond it are "apart".
constexpr double kApproachSearch_m = 2.0e-6;

std::array<int, 3> box_nodes(const ShearSuspensionConfig& c) {
  const double dx = c.numerics.dx_m;
  return {static_cast<int>(std::lround(c.length_m / dx)), static_cast<int>(std::lround(c.gap_m / dx)),
          static_cast<int>(std::lround(c.width_m / dx))};
}

/// The rest mesh of every cell: the RBC of [membrane], or (shape = "sphere") the subdivided sphere of the same
/// vertex count with the RBC's volume, for the stiff-sphere check of the stresslet against Einstein's 2.5.
TriangleMesh rest_mesh(const ShearSuspensionConfig& c) {
  TriangleMesh rbc = build_membrane_mesh(c.membrane);
  if (c.shape == CellShapeKind::biconcave) return rbc;
  return sphere_cell_mesh(c.membrane, std::cbrt(3.0 * mesh_volume_m3(rbc) / (4.0 * std::numbers::pi)));
}

struct SuspensionRun {
  common::UnitConverter units;
  std::array<int, 3> nodes{};
  Vec3 origin_m;
  std::unique_ptr<FluidLattice> lattice;
  std::unique_ptr<CellSuspension> cells;
  double cell_volume_m3 = 0.0;
};

std::unique_ptr<SuspensionRun> build(const ShearSuspensionConfig& c, const Placement& placement, const TriangleMesh& rest) {
  const CellNumerics& n = c.numerics;
  auto r = std::make_unique<SuspensionRun>(SuspensionRun{
      .units = common::UnitConverter(common::LatticeScales{.dx_m = n.dx_m, .dt_s = n.dt_s, .rho_kg_m3 = c.density_kg_m3}),
      .nodes = box_nodes(c), .origin_m = {0.0, 0.5 * n.dx_m, 0.0}, .lattice = nullptr, .cells = nullptr,
      .cell_volume_m3 = placement.cell_volume_m3});
  // Node j sits at y = (j + 1/2) dx: the half-way walls are at y = 0 and y = H (as the shear case).
  r->lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = r->nodes, .periodic = {true, false, true}, .collision = n.collision,
                  .streaming = n.streaming}, MPI_COMM_WORLD);
  r->lattice->enable_force_field();
  const double h_m = r->nodes[1] * n.dx_m;
  const double u_wall_lu = r->units.to_lattice_velocity(0.5 * c.shear_rate_1_s * h_m);
  r->lattice->set_face_wall_velocity(1, 0, {-u_wall_lu, 0.0, 0.0});
  r->lattice->set_face_wall_velocity(1, 1, {u_wall_lu, 0.0, 0.0});
  const double ny = r->nodes[1];
  r->lattice->initialize([&](const Vec3& p) {
    return NodeInit{.rho_lu = 1.0, .u_lu = {u_wall_lu * (2.0 * (p.y + 0.5) / ny - 1.0), 0.0, 0.0}};
  });
  // The plates repel the membrane with the contact spring (range d0, stiffness k) along y.
  const CellContactSpec contact = c.contact;
  const auto walls = [contact, h_m](int, std::span<const Vec3> x, std::vector<Vec3>& f) {
    if (contact.range_m <= 0.0) return;
    for (std::size_t v = 0; v < x.size(); ++v) {
      const double below = x[v].y, above = h_m - x[v].y;
      if (below < contact.range_m) f[v].y += contact.stiffness_N_m * (contact.range_m - below);
      if (above < contact.range_m) f[v].y -= contact.stiffness_N_m * (contact.range_m - above);
    }
  };
  r->cells = std::make_unique<CellSuspension>(
      *r->lattice, r->units,
      CouplingSettings{.ibm = n.ibm, .membrane_every = n.membrane_every, .median_filter = true,
                       .membrane_force = n.membrane_force, .traction_area = n.traction_area,
                       .lattice_origin_m = r->origin_m, .drive_on_enclosed_volume = n.drive_on_enclosed_volume},
      contact, walls);
  MembraneParameters material = c.membrane.material;
  material.density_kg_m3 *= n.membrane_mass_factor;
  for (const auto& x : placement.cells_m) {
    TriangleMesh mesh = rest;   // topology and stress-free shape of the rest cell, placed
    mesh.vertices_m = x;
    r->cells->add_cell(std::make_unique<NpfemSolver>(mesh, material, c.membrane.solver, n.membrane_every * n.dt_s));
  }
  return r;
}

void check_contact_stability(const ShearSuspensionConfig& c, const SuspensionRun& r, const std::string& file) {
  if (r.cells->size() == 0) return;
  const double m_vertex = r.cells->membrane(0).vertex_mass_kg();
  const double h = c.numerics.membrane_every * c.numerics.dt_s;
  const double ratio = c.contact.stiffness_N_m * h * h / m_vertex;
  if (ratio > kContactStabilityMax) {
    throw common::ConfigError(fmt::format("{}: [cells] contact_stiffness_N_m = {:g} gives k h^2 / m_vertex = {:.3g} > {:g} "
                                          "(explicit contact spring unstable); lower it below {:.3g} N/m", file,
                                          c.contact.stiffness_N_m, ratio, kContactStabilityMax,
                                          kContactStabilityMax * m_vertex / (h * h)));
  }
}

SuspensionSample sample_state(const ShearSuspensionConfig& c, const SuspensionRun& r, double time_s) {
  SuspensionSample s;
  s.time_s = time_s;
  s.min_wall_distance_m = std::numeric_limits<double>::infinity();
  std::vector<std::vector<Vec3>> x(static_cast<std::size_t>(r.cells->size()));
  for (int i = 0; i < r.cells->size(); ++i) {
    auto& xi = x[static_cast<std::size_t>(i)];
    xi = r.cells->membrane(i).positions_m();
    const auto& f = r.cells->cell(i).report().fluid_forces_N;
    if (f.size() == xi.size()) s.stresslet_xy_N_m += stresslet(xi, f)[0][1];   // none before the first membrane step
    s.di_mean += measure_cell_shape(xi).deformation_index() / r.cells->size();
    s.volume_m3 += r.cells->membrane(i).volume_m3();
    for (const auto& p : xi) s.min_wall_distance_m = std::min({s.min_wall_distance_m, p.y, c.gap_m - p.y});
  }
  // The closest approach: the binned contact search over a wider range, into forces that are thrown away (any
  // positive stiffness: the search skips a spring of none).
  const double search = std::max(kApproachSearch_m, c.contact.range_m);
  std::vector<std::span<const Vec3>> spans(x.begin(), x.end());
  std::vector<std::vector<Vec3>> none;
  for (const auto& xi : x) none.emplace_back(xi.size());
  s.min_cell_distance_m =
      x.size() < 2 ? search
                   : add_cell_contact_forces(spans, none, {.range_m = search, .stiffness_N_m = 1.0,
                                                           .period_m = c.contact.period_m}).min_distance_m;
  s.contact_pairs = r.cells->contact_report().pairs;
  return s;
}

void write_membranes(const SuspensionRun& r, const common::RunContext& ctx, int frame, common::PvdSeries& pvd) {
  if (ctx.rank() != 0) return;
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::int32_t> index;
  for (int i = 0; i < r.cells->size(); ++i) {
    const auto& m = r.cells->membrane(i);
    const auto x = wrapped_into_box(m.positions_m(), r.origin_m, r.nodes, r.units.dx_m(), {true, false, true});
    const int offset = static_cast<int>(points.size());
    points.insert(points.end(), x.begin(), x.end());
    for (const auto& t : m.triangles()) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    index.insert(index.end(), x.size(), i);
  }
  common::VtkPolyData poly(points, triangles);
  poly.add_point_scalar("cell", index);
  const std::string name = fmt::format("membranes_{:05d}.vtp", frame);
  poly.write(ctx.folder().vtk_dir() / name);
  pvd.add(r.units.to_si_time(static_cast<double>(r.lattice->steps_done())), "vtk/" + name);
}

}  // namespace

int run_shear_suspension(const common::CaseRequest& request) {
  const std::string type = "shear-suspension";
  const std::string file = request.config->name();
  const ShearSuspensionConfig c = read_shear_suspension(*request.config, request.quick);
  require_lattice_memory(*request.config, box_nodes(c),
                         {{"[geometry] length_m", c.length_m, true}, {"[geometry] gap_m", c.gap_m, true},
                          {"[geometry] width_m", c.width_m, true}, {"[numerics] dx_m", c.numerics.dx_m, true}});
  const TriangleMesh rest = rest_mesh(c);
  const PlacementBox box{.lower_m = {0.0, 0.0, 0.0}, .upper_m = {c.length_m, c.gap_m, c.width_m},
                         .periodic = {true, false, true}};
  const PlacementSpec spec{.hematocrit = c.hematocrit, .min_gap_m = c.placement_gap_m,
                           .wall_clearance_m = std::max(kWallClearanceDx * c.numerics.dx_m, c.contact.range_m),
                           .seed = c.seed};
  Placement placement;
  const auto placing = std::chrono::steady_clock::now();
  try {
    placement = place_cells(rest, box, spec);
  } catch (const PlacementImpossible& e) {
    throw common::ConfigError(fmt::format("{}: [cells] hematocrit = {:g}: {}", file, c.hematocrit, e.what()));
  }
  const double placement_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - placing).count();
  if (request.resume) {
    throw common::ConfigError(fmt::format("{}: the shear-suspension case writes no checkpoints yet: --resume cannot "
                                          "continue it; start it anew", file));
  }
  common::RunContext ctx = common::RunContext::start(request, type);
  auto run = build(c, placement, rest);
  SuspensionRun& r = *run;
  check_contact_stability(c, r, file);
  if (ctx.rank() == 0) r.units.write(ctx.folder().file("units.txt"));
  ctx.log().info("{}: {} cells (hematocrit {:.4g}, asked {:.4g}; {}: {} placement tries{}, {:.1f} s), shear rate {:.4g} "
                 "1/s, Re = {:.4g}, lattice {}x{}x{}, dx = {:g} m, dt = {:.4g} s, tau = {:.3f}, membrane mass factor {:.3g}",
                 type, r.cells->size(), placement.hematocrit, c.hematocrit, placement_method_name(placement.method),
                 placement.attempts,
                 placement.method == PlacementMethod::growth_packing
                     ? fmt::format(", grown from {:.3f} of full size in {} sweeps", placement.packing_start_scale,
                                   placement.packing_sweeps)
                     : std::string(),
                 placement_seconds, c.shear_rate_1_s, c.reynolds,
                 r.nodes[0], r.nodes[1], r.nodes[2], c.numerics.dx_m, c.numerics.dt_s, c.numerics.collision.tau,
                 c.numerics.membrane_mass_factor);
  if (const std::string w = kernel_width_warning(c.numerics.ibm.kernel, c.numerics.dx_m, c.shape); !w.empty()) ctx.log().warning("{}", w);
  ShearSuspensionSeries series(c, r.cells->size(), placement.cell_volume_m3);
  std::unique_ptr<common::CsvWriter> csv;
  std::unique_ptr<common::PvdSeries> pvd;
  if (ctx.rank() == 0) {
    csv = std::make_unique<common::CsvWriter>(ctx.folder().file("timeseries.csv"), ShearSuspensionSeries::columns());
    pvd = std::make_unique<common::PvdSeries>(ctx.folder().file("membranes.pvd"));
  }
  const long max_steps = r.units.to_lattice_steps(c.max_time_s);
  common::TimeLoop loop(max_steps, 0);
  CellSuspension& cells = *r.cells;
  loop.add("membrane_solve", [&cells] { cells.membrane_solve(); });
  loop.add("ibm_forcing", [&cells] { cells.ibm_forcing(); });
  loop.add("lbm_stream_collide", [&r] { r.lattice->stream_collide(); });
  loop.add("halo_exchange", [&r] { r.lattice->exchange_halos(); });
  loop.add("lbm_boundaries", [&r] { r.lattice->apply_boundaries(); });
  loop.add("markers_advect", [&cells] { cells.markers_advect(); });
  int frame = 0;
  const long frame_every = c.vtk_every_s > 0.0 ? r.units.to_lattice_steps(c.vtk_every_s) : 0;
  loop.every(frame_every, "write_frames", [&] {
    if (pvd) write_membranes(r, ctx, frame, *pvd);
    ++frame;
  });
  common::Progress progress(type, max_steps, ctx.show_progress() && !request.quiet);
  while (loop.step() < loop.end_step()) {
    loop.run_steps(c.sample_every_steps);
    r.lattice->check_health();
    series.add(sample_state(c, r, r.units.to_si_time(static_cast<double>(loop.step()))));
    if (csv) csv->row(series.row(series.samples().size() - 1));
    progress.update(loop.step());
  }
  progress.finish();
  if (pvd) write_membranes(r, ctx, frame, *pvd);
  const double simulated_s = r.units.to_si_time(static_cast<double>(loop.step()));
  ctx.log().info("stopped after {} steps ({:.4g} s simulated); wall time per stage:\n{}", loop.step(), simulated_s,
                 loop.timing_table());
  nlohmann::json summary;
  summary["results"] = series.results();
  summary["groups"] = groups_of(summary["results"]);
  NpfemStatistics all;   // the membrane solves of every cell together
  for (int i = 0; i < cells.size(); ++i) {
    const NpfemStatistics& s = cells.membrane(i).statistics();
    all.steps += s.steps;
    all.iterations += s.iterations;
    all.unconverged_steps += s.unconverged_steps;
    all.line_search_stops += s.line_search_stops;
    all.iteration_cap_stops += s.iteration_cap_stops;
    all.unconverged_gradient_sum += s.unconverged_gradient_sum;
  }
  summary["numerics"] = {{"dx_m", c.numerics.dx_m},
                         {"dt_s", c.numerics.dt_s},
                         {"membrane_step_s", static_cast<double>(c.numerics.membrane_every) * c.numerics.dt_s},
                         {"tau", c.numerics.collision.tau},
                         {"lattice_weissenberg", c.numerics.lattice_weissenberg},
                         {"membrane_mass_factor", c.numerics.membrane_mass_factor},
                         {"contact_range_m", c.contact.range_m},
                         {"contact_stiffness_N_m", c.contact.stiffness_N_m},
                         {"placement_gap_m", c.placement_gap_m},
                         {"placement_seed", c.seed},
                         {"placement_tries", placement.attempts},
                         {"placement_method", placement_method_name(placement.method)},
                         {"placement_packing_sweeps", placement.packing_sweeps},
                         {"steps", loop.step()},
                         {"simulated_time_s", simulated_s},
                         {"wall_s_per_simulated_ms", loop.wall_s_per_simulated_ms(c.numerics.dt_s)},
                         {"membrane_steps_all_cells", all.steps},
                         {"membrane_iterations_per_step", all.steps > 0 ? static_cast<double>(all.iterations) / static_cast<double>(all.steps) : 0.0},
                         {"membrane_unconverged_steps", all.unconverged_steps},
                         {"membrane_solve", membrane_solve_summary(all)}};
  summary["timings"] = loop.timings();
  common::CheckList checks;   // the case measures; it checks only its membrane solves
  expect_membrane_converged(checks, summary["numerics"]["membrane_solve"], request.quick, "all cells");
  ctx.write_summary(summary, checks);
  checks.print(ctx.log(), "shear-suspension");
  return checks.exit_code();
}

}  // namespace hs::resolved
