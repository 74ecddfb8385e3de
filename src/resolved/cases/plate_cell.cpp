// SPDX-License-Identifier: MIT
// The plate cases: one RBC between parallel walls in simple shear or in plane Poiseuille flow.
#include "resolved/cases/plate_cell.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>

#include "common/run_context.hpp"
#include "resolved/cases/cell_simulation.hpp"
#include "resolved/cases/lattice_budget.hpp"
#include "resolved/cases/plate_cell_checks.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/cases/plate_cell_series.hpp"
#include "resolved/cases/stokes_analogue.hpp"
#include "resolved/measure/stresslet.hpp"
#include "resolved/measure/cell_shape.hpp"
#include "resolved/measure/equivalent_ellipsoid.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

struct PlateCellRun : CellSimulation {
  PlateCellConfig c;
  int marker = 0;   // the vertex whose phase about the centroid is tracked
};

std::array<int, 3> plate_nodes(const PlateCellConfig& c) {
  const double dx = c.numerics.dx_m;
  return {static_cast<int>(std::lround(c.length_m / dx)), static_cast<int>(std::lround(c.gap_m / dx)),
          static_cast<int>(std::lround(c.width_m / dx))};
}

/// With the cell's mass as the membrane carries it (its density times the mass factor, times the rest volume).
double membrane_cell_stokes_number(const PlateCellConfig& c, const NpfemSolver& membrane) {
  return cell_stokes_number(membrane.vertex_mass_kg() * membrane.vertex_count(), c.shear_rate_1_s,
                            c.density_kg_m3 * c.kinematic_viscosity_m2_s, kCellRadius_m);
}

/// Node j sits at y = (j + 1/2) dx: the half-way walls of the y faces are then at y = 0 and y = H = ny dx.
std::unique_ptr<PlateCellRun> build(const PlateCellConfig& c) {
  const CellNumerics& n = c.numerics;
  auto run = std::make_unique<PlateCellRun>(PlateCellRun{
      {.units = common::UnitConverter(common::LatticeScales{.dx_m = n.dx_m, .dt_s = n.dt_s, .rho_kg_m3 = c.density_kg_m3}),
       .nodes = plate_nodes(c),
       .origin_m = {0.0, 0.5 * n.dx_m, 0.0}, .lattice = nullptr, .membrane = nullptr, .cell = nullptr, .cytoplasm = nullptr},
      c, 0});
  auto& r = *run;
  const double h_m = r.nodes[1] * n.dx_m;
  r.lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = r.nodes, .periodic = {true, false, true}, .collision = n.collision,
                  .streaming = n.streaming}, MPI_COMM_WORLD);
  r.lattice->enable_force_field();
  if (c.flow == PlateFlow::shear) {
    // Started on the Couette profile: the wall speed is ~0.04 in lattice units at most, no start-up wave to fear.
    const double u_wall_lu = r.units.to_lattice_velocity(0.5 * c.shear_rate_1_s * h_m);
    r.lattice->set_face_wall_velocity(1, 0, {-u_wall_lu, 0.0, 0.0});
    r.lattice->set_face_wall_velocity(1, 1, {u_wall_lu, 0.0, 0.0});
    const double ny = r.nodes[1];
    r.lattice->initialize([&](const Vec3& p) {
      return NodeInit{.rho_lu = 1.0, .u_lu = {u_wall_lu * (2.0 * (p.y + 0.5) / ny - 1.0), 0.0, 0.0}};
    });
  } else {
    r.lattice->initialize();   // at rest; the drive is ramped up (see drive_lu)
  }
  const Vec3 centre{0.5 * c.length_m, c.initial_height * h_m, 0.5 * c.width_m};
  add_coupled_cell(r,
                   c.shape == CellShapeKind::sphere ? sphere_cell_mesh(c.membrane, kCellRadius_m)
                                                    : cell_mesh_with_disc_axis(c.membrane, c.disc_axis),
                   c.membrane, n, centre);
  // Marker: the vertex furthest along the flow, on the rim in the shear plane for the default orientations.
  const auto x = r.membrane->positions_m();
  for (std::size_t v = 1; v < x.size(); ++v) {
    if (x[v].x > x[static_cast<std::size_t>(r.marker)].x) r.marker = static_cast<int>(v);
  }
  return run;
}

/// Plane Poiseuille drive g = 8 nu U_max / H^2 (resolved-methods.md 1.3), switched on over spin_up_steps.
double drive_lu(const PlateCellRun& r, long step) {
  const PlateCellConfig& c = r.c;
  const double g_m_s2 = 8.0 * c.kinematic_viscosity_m2_s * c.u_max_m_s / (c.gap_m * c.gap_m);
  return smooth_ramp(step, c.spin_up_steps) * r.units.to_lattice_acceleration(g_m_s2);
}

/// Orientation of the cell's outline in the shear plane (x, y): the long axis of the 2-D gyration tensor of the
/// vertices projected on that plane, against the flow, in (-pi/2, pi/2]. Unlike the longest 3-D axis it is defined for
/// a disc flipping about z (whose 3-D long axes are degenerate: one always lies along z). For a disc lying in the
/// shear plane the outline is nearly circular and the angle is noise: read the marker phase there.
double shear_plane_inclination(std::span<const Vec3> x, const Vec3& centroid_m) {
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const auto& p : x) {
    const Vec3 d = p - centroid_m;
    sxx += d.x * d.x;
    syy += d.y * d.y;
    sxy += d.x * d.y;
  }
  double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  if (angle <= -0.5 * std::numbers::pi) angle += std::numbers::pi;
  return angle;
}

PlateCellSample sample_state(const PlateCellRun& r, double time_s) {
  const auto x = r.membrane->positions_m();
  const CellShape shape = measure_cell_shape(x);
  PlateCellSample s;
  s.time_s = time_s;
  s.di = shape.deformation_index();
  s.di_gyration = shape.gyration_deformation_index();
  s.inclination_rad = shear_plane_inclination(x, shape.centroid_m);
  const Vec3 d = x[static_cast<std::size_t>(r.marker)] - shape.centroid_m;
  s.marker_phase_rad = std::atan2(d.y, d.x);
  s.centroid_m = shape.centroid_m;
  for (const auto& v : r.membrane->velocities_m_s()) s.velocity_m_s += v;
  s.velocity_m_s = s.velocity_m_s / static_cast<double>(x.size());
  s.energy = membrane_energy_snapshot(*r.membrane, time_s);
  const auto& f = r.cell->report().fluid_forces_N;
  if (f.size() == x.size()) s.stresslet_xy_N_m = stresslet(x, f)[0][1];   // none before the first membrane step
  s.volume_m3 = r.membrane->volume_m3();
  s.taylor_deformation = equivalent_ellipsoid(x, r.membrane->triangles()).shear_plane_taylor_deformation({0.0, 0.0, 1.0});
  return s;
}

/// How often (in samples) a run with [run] stop_when_settled tests whether it may stop.
constexpr std::size_t kSettledCheckEvery = 50;

int run_plate_cell(const common::CaseRequest& request, PlateFlow flow) {
  const char* type = flow == PlateFlow::shear ? "shear" : "migration";
  const PlateCellConfig c = read_plate_cell(*request.config, flow, request.quick);
  require_lattice_memory(*request.config, plate_nodes(c),
                         {{"[geometry] length_m", c.length_m, true}, {"[geometry] gap_m", c.gap_m, true},
                          {"[geometry] width_m", c.width_m, true}, {"[numerics] dx_m", c.numerics.dx_m, true}});
  common::RunContext ctx = common::RunContext::start(request, type);
  auto run = build(c);
  PlateCellRun& r = *run;
  if (ctx.rank() == 0) r.units.write(ctx.folder().file("units.txt"));
  ctx.log().info("{}: Re = {:.4g}, shear rate {:.4g} 1/s, U_max {:.4g} m/s, lattice {}x{}x{}, dx = {:g} m, dt = {:.4g} s, "
                 "tau = {:.3f}, lattice velocity {:.4g}, lattice Weissenberg {:.3g}, membrane mass factor {:.3g}, "
                 "viscosity ratio {:.4g} (cytoplasm tau {:.3f}){}", type,
                 c.reynolds,
                 c.shear_rate_1_s, c.u_max_m_s, r.nodes[0], r.nodes[1], r.nodes[2], c.numerics.dx_m, c.numerics.dt_s,
                 c.numerics.collision.tau, c.numerics.lattice_velocity, c.numerics.lattice_weissenberg,
                 c.numerics.membrane_mass_factor, c.numerics.viscosity_ratio,
                 c.numerics.viscosity_ratio != 1.0 ? c.numerics.inner_collision.tau : c.numerics.collision.tau,
                 c.shape == CellShapeKind::sphere ? fmt::format(", a spherical capsule of radius {:g} m", kCellRadius_m) : "");
  if (const std::string w = kernel_width_warning(c.numerics.ibm.kernel, c.numerics.dx_m, c.shape); !w.empty()) {
    ctx.log().warning("{}", w);
  }
  if (c.stokes_analogue) {
    ctx.log().info("Stokes-flow analogue: every viscosity x {:g} (Ca, viscosity ratio and Bq kept)", c.analogue_viscosity_factor);
  }
  const double stokes_number = membrane_cell_stokes_number(c, *r.membrane);
  // The analogue chose its factor from the mesh's volume, npFEM lumps the same volume: round-off must not warn at the cap.
  if (stokes_number > kAnalogueMaxCellStokes * (1.0 + 1e-9)) {
    ctx.log().warning("cell Stokes number {:.3g} (membrane mass factor {:.3g}) is above {}: the membrane's numerical mass "
                      "changes the motion (docs/resolved-coupling.md, \"The membrane's mass in the shear analogue\"); "
                      "give [flow] capillary with stokes_analogue = true, or lower the mass factor",
                      stokes_number, c.numerics.membrane_mass_factor, kAnalogueMaxCellStokes);
  }
  PlateCellSeries series(c);
  int frame = 0;
  long first_step = 0;
  if (ctx.resuming()) {
    std::vector<double> packed;
    first_step = read_cell_checkpoint(r, packed, ctx, frame);
    series.unpack(packed);
  }
  const CellOutputs out = open_cell_outputs(ctx, PlateCellSeries::columns());
  for (std::size_t i = 0; i < series.samples().size(); ++i) out.row(series.row(i));   // rows up to the checkpoint
  const long max_steps = r.units.to_lattice_steps(c.max_time_s);
  common::TimeLoop loop(max_steps, first_step);
  if (flow == PlateFlow::poiseuille) {
    loop.add("body_force_ramp", [&] { r.lattice->set_body_force({drive_lu(r, loop.step()), 0.0, 0.0}); });
  }
  add_coupled_stages(loop, r);
  const long frame_every = c.vtk_every_s > 0.0 ? r.units.to_lattice_steps(c.vtk_every_s) : 0;
  loop.every(frame_every, "write_frames", [&] { out.write_frame(r, ctx, frame); });
  common::Progress progress(type, max_steps, ctx.show_progress() && !request.quiet);
  const SampledRunHooks hooks{.sample =
                                  [&] {
                                    series.add(sample_state(r, r.units.to_si_time(static_cast<double>(loop.step()))));
                                    out.row(series.row(series.samples().size() - 1));
                                  },
                              .done =
                                  [&] {
                                    // Settled tank-treading, checked every kSettledCheckEvery samples (the test reads
                                    // the whole series).
                                    const std::size_t n = series.samples().size();
                                    return c.stop_when_settled && n % kSettledCheckEvery == 0 &&
                                           series.tank_treading_settled();
                                  },
                              .pack = [&] { return series.pack(); }};
  const bool stopped_early = run_sampled(loop, r, ctx, c.sample_every_steps, c.checkpoint_every_wall_s, progress, hooks, frame);
  out.write_frame(r, ctx, frame);
  const double simulated_s = r.units.to_si_time(static_cast<double>(loop.step()));
  ctx.log().info("stopped after {} steps ({:.4g} s simulated); wall time per stage:\n{}", loop.step(), simulated_s,
                 loop.timing_table());
  nlohmann::json summary;
  summary["results"] = series.results();
  summary["results"]["membrane_energy"] = series.energy_results();
  summary["groups"] = groups_of(summary["results"]);
  common::CheckList checks = plate_cell_checks(c, summary["results"], series.samples());
  summary["numerics"] = {{"dx_m", c.numerics.dx_m},
                         {"dt_s", c.numerics.dt_s},
                         {"membrane_step_s", static_cast<double>(c.numerics.membrane_every) * c.numerics.dt_s},
                         {"tau", c.numerics.collision.tau},
                         {"viscosity_ratio", c.numerics.viscosity_ratio},   // cytoplasm / plasma; 1: one fluid
                         {"tau_cytoplasm", c.numerics.viscosity_ratio != 1.0 ? c.numerics.inner_collision.tau : c.numerics.collision.tau},
                         // (tau+ - 1/2)(tau- - 1/2) outside and in: the IBM's slip grows with it (collision_params.hpp)
                         {"lambda", c.numerics.collision.bulk_lambda()},
                         {"lambda_cytoplasm", c.numerics.viscosity_ratio != 1.0 ? c.numerics.inner_collision.bulk_lambda() : c.numerics.collision.bulk_lambda()},
                         {"cytoplasm_nodes", r.cytoplasm ? static_cast<long>(r.cytoplasm->inner_nodes()) : 0L},
                         {"lattice_weissenberg", c.numerics.lattice_weissenberg},   // gamma (tau - 1/2) dt
                         {"membrane_mass_factor", c.numerics.membrane_mass_factor},
                         // The inertia the mass factor gives the cell (m gamma_dot / (6 pi mu a); warned above 0.05)
                         {"cell_stokes_number", stokes_number},
                         // [flow] stokes_analogue: every viscosity's multiplier (1 without it)
                         {"analogue_viscosity_factor", c.analogue_viscosity_factor},
                         {"membrane_velocity_relaxation", r.membrane->velocity_relaxation()},   // C_alpha per npFEM step
                         {"steps", loop.step()},
                         {"stopped_when_settled", stopped_early},
                         {"simulated_time_s", simulated_s},
                         {"wall_s_per_simulated_ms", loop.wall_s_per_simulated_ms(c.numerics.dt_s)},
                         {"membrane_unconverged_steps", r.membrane->statistics().unconverged_steps},
                         {"membrane_solve", membrane_solve_summary(r.membrane->statistics())}};
  summary["timings"] = loop.timings();
  expect_membrane_converged(checks, summary["numerics"]["membrane_solve"], request.quick);
  ctx.write_summary(summary, checks);
  checks.print(ctx.log(), type);
  return checks.exit_code();
}

}  // namespace

int run_shear(const common::CaseRequest& request) { return run_plate_cell(request, PlateFlow::shear); }

int run_migration(const common::CaseRequest& request) { return run_plate_cell(request, PlateFlow::poiseuille); }

}  // namespace hs::resolved
