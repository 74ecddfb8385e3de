// SPDX-License-Identifier: MIT
// The tube-cell case: one RBC in the periodic campaign tube, drag (centre fixed) or lift (axial motion only).
#include "resolved/cases/tube_cell.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "common/check_list.hpp"
#include "common/dimensionless_groups.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/run_context.hpp"
#include "resolved/cases/cell_simulation.hpp"
#include "resolved/cases/lattice_budget.hpp"
#include "resolved/cases/tube_cell_config.hpp"
#include "resolved/cases/tube_cell_series.hpp"
#include "resolved/measure/cell_shape.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

/// Odd node count across (the axis passes through a node) with two spare nodes outside the wall on each side.
std::array<int, 3> lattice_nodes(const TubeCellConfig& c) {
  int across = static_cast<int>(std::floor((2.0 * c.radius_m + 4.0 * c.dx_m) / c.dx_m + 1e-9)) + 1;
  if (across % 2 == 0) ++across;
  return {across, across, static_cast<int>(std::lround(c.length_m / c.dx_m))};
}

/// Everything one run holds: lattice, membrane, coupling (CellSimulation) and the case.
struct TubeCellRun : CellSimulation {
  TubeCellConfig c;
};

CellNumerics numerics_of(const TubeCellConfig& c) {
  return {.dx_m = c.dx_m, .lattice_velocity = c.lattice_velocity, .max_tau = c.max_tau, .collision = c.collision,
          .wall = c.wall, .membrane_every = c.membrane_every, .membrane_mass_factor = c.membrane_mass_factor,
          .ibm = c.ibm, .traction_area = c.traction_area, .drive_on_enclosed_volume = c.drive_on_enclosed_volume,
          .membrane_force = c.membrane_force, .viscosity_ratio = c.viscosity_ratio, .inner_collision = c.inner_collision,
          .dt_s = c.dt_s};
}

std::unique_ptr<TubeCellRun> build(const TubeCellConfig& c) {
  auto run = std::make_unique<TubeCellRun>(TubeCellRun{
      {.units = common::UnitConverter(common::LatticeScales{.dx_m = c.dx_m, .dt_s = c.dt_s, .rho_kg_m3 = c.density_kg_m3}),
       .nodes = lattice_nodes(c), .origin_m = {}, .lattice = nullptr, .membrane = nullptr, .cell = nullptr, .cytoplasm = nullptr},
      c});
  auto& r = *run;
  const double centre_lu = 0.5 * (r.nodes[0] - 1);
  r.origin_m = {-centre_lu * c.dx_m, -centre_lu * c.dx_m, 0.0};
  const common::Tube tube(common::TubeSpec{
      .start_m = {0.0, 0.0, -c.dx_m}, .end_m = {0.0, 0.0, c.length_m + c.dx_m}, .radius_m = c.radius_m});
  r.lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = r.nodes, .periodic = {false, false, true}, .collision = c.collision,
                  .streaming = c.streaming}, MPI_COMM_WORLD);
  r.lattice->set_shape(tube, ShapePlacement{.origin = r.origin_m, .spacing = c.dx_m}, c.wall);
  // Poiseuille drive g = 4 nu U_max / R^2 (resolved-methods.md 1.3). The fluid starts at rest: starting from the
  // undisturbed profile stops it impulsively at the cell, whose pressure waves trip the Mach watchdog at
  // lattice_velocity 0.05; spin-up takes a few R^2/nu, a small part of one tumbling period.
  r.lattice->set_body_force({});
  r.lattice->enable_force_field();
  r.lattice->initialize();
  // The disc axis turned from z to y: the disc then lies in the plane of the flow (z) and the radial direction (x),
  // the plane in which it tumbles or tank-treads.
  add_coupled_cell(r, cell_mesh_with_disc_axis(c.membrane, 1), c.membrane, numerics_of(c),
                   Vec3{c.radial_position * c.radius_m, 0.0, 0.5 * c.length_m});
  r.membrane->set_center_constraint(c.setup == TubeCellSetup::drag ? CenterConstraint::fixed : CenterConstraint::axis,
                                    {0.0, 0.0, 1.0});
  return run;
}

/// Poiseuille drive g = 4 nu U_max / R^2 (resolved-methods.md 1.3), switched on smoothly over spin_up_steps: at
/// large tau the lattice stress lags the forcing by ~tau steps, and a sudden drive overshoots U_max (measured at
/// tau = 60.5: lattice Mach 0.10 after 12 steps, the watchdog stops the run).
double drive_lu(const TubeCellRun& r, long step) {
  const TubeCellConfig& c = r.c;
  const double g_m_s2 = 4.0 * c.kinematic_viscosity_m2_s * c.u_max_m_s / (c.radius_m * c.radius_m);
  const double share = smooth_ramp(step, c.spin_up_steps);
  return share * r.units.to_lattice_acceleration(g_m_s2);
}

/// Relaxation time of the (mass-scaled) cell, m / (3 pi mu d_p), times the tube's shear rate scale U_max / R.
double cell_stokes_number(const TubeCellConfig& c, double volume_m3) {
  const double mass_kg = c.membrane_mass_factor * c.membrane.material.density_kg_m3 * volume_m3;
  const double d_p = std::cbrt(6.0 * volume_m3 / std::numbers::pi);
  const double mu = c.density_kg_m3 * c.kinematic_viscosity_m2_s;
  return mass_kg / (3.0 * std::numbers::pi * mu * d_p) * c.u_max_m_s / c.radius_m;
}

TubeCellSample sample_state(const TubeCellRun& r, double time_s, const Vec3& force_N, const Vec3& traction_N) {
  TubeCellSample s;
  s.time_s = time_s;
  s.force_N = force_N;
  s.traction_force_N = traction_N;
  const auto x = r.membrane->positions_m();
  const CellShape shape = measure_cell_shape(x);
  s.centroid_m = shape.centroid_m;
  const double rr = std::hypot(s.centroid_m.x, s.centroid_m.y);
  const Vec3 radial = rr > 1e-12 ? Vec3{s.centroid_m.x / rr, s.centroid_m.y / rr, 0.0} : Vec3{1.0, 0.0, 0.0};
  s.di = shape.deformation_index();
  s.inclination_rad = inclination_angle(shape, {0.0, 0.0, 1.0}, radial);
  const Vec3 d = x[0] - s.centroid_m;
  s.marker_phase_rad = std::atan2(common::dot(d, radial), d.z);
  double vz = 0.0;
  for (const auto& v : r.membrane->velocities_m_s()) vz += v.z;
  s.axial_velocity_m_s = vz / static_cast<double>(x.size());
  return s;
}

/// The run's result line on stdout: the period (or plain) averages of C_d, C_l and DI that its summary.json holds.
void print_result(common::Log& log, const nlohmann::json& results, bool drag, bool settled) {
  auto number = [&results](const char* key) {
    return results.contains(key) && results[key].is_number() ? results[key].get<double>() : std::nan("");
  };
  log.result("tube-cell ({}): C_d {:.6g}, C_l {:.6g}, DI {:.4f}, averaged over {} periods; {}", drag ? "drag" : "lift",
             number("cd_mean"), number("cl_mean"), number("di_mean"), number("periods_averaged"),
             settled ? "settled" : "NOT settled (stopped at max_time_s)");
}

}  // namespace

int run_tube_cell(const common::CaseRequest& request) {
  const TubeCellConfig c = read_tube_cell(*request.config, request.quick);
  require_lattice_memory(*request.config, lattice_nodes(c),
                         {{"[geometry] radius_m", c.radius_m, true}, {"[geometry] length_m", c.length_m, true},
                          {"[numerics] dx_m", c.dx_m, true}});
  common::RunContext ctx = common::RunContext::start(request, "tube-cell");
  auto run = build(c);
  TubeCellRun& r = *run;
  if (ctx.rank() == 0) r.units.write(ctx.folder().file("units.txt"));
  ctx.log().info("tube-cell ({}): r* = {}, Re = {}, U_max = {:.4g} m/s, lattice {}x{}x{}, dx = {:g} m, dt = {:.4g} s, "
                 "tau = {:.3f}, peak lattice velocity {:.4g}, membrane every {} steps, viscosity ratio {:.4g} "
                 "(cytoplasm tau {:.3f})",
                 c.setup == TubeCellSetup::drag ? "drag" : "lift", c.radial_position, c.reynolds, c.u_max_m_s,
                 r.nodes[0], r.nodes[1], r.nodes[2], c.dx_m, c.dt_s, c.collision.tau, c.lattice_velocity,
                 c.membrane_every, c.viscosity_ratio, c.viscosity_ratio != 1.0 ? c.inner_collision.tau : c.collision.tau);
  if (const std::string w = kernel_width_warning(numerics_of(c).ibm.kernel, c.dx_m); !w.empty()) ctx.log().warning("{}", w);
  TubeCellSeries series(c, r.membrane->rest_volume_m3());
  int frame = 0;
  long first_step = 0;
  if (ctx.resuming()) {
    std::vector<double> packed;
    first_step = read_cell_checkpoint(r, packed, ctx, frame);
    series.unpack(packed);
    ctx.log().info("resumed at step {} with {} samples", first_step, series.size());
  }
  const CellOutputs out = open_cell_outputs(ctx, tube_cell_columns());
  for (const auto& s : series.samples()) out.row(series.row(s));   // rows up to the checkpoint (resume)
  const long max_steps = r.units.to_lattice_steps(c.max_time_s);
  const long frame_every = c.vtk_every_s > 0.0 ? r.units.to_lattice_steps(c.vtk_every_s) : 0;
  Vec3 force_sum_lu, traction_sum_N;
  long summed = 0;
  common::TimeLoop loop(max_steps, first_step);
  loop.add("body_force_ramp", [&] { r.lattice->set_body_force({0.0, 0.0, drive_lu(r, loop.step())}); });
  add_coupled_stages(loop, r);
  loop.add("force_accumulate", [&] {
    force_sum_lu -= r.cell->report().forcing.total_force_lu;   // the force on the cell is minus that on the fluid
    traction_sum_N += r.cell->report().fluid_force_N;
    ++summed;
  });
  loop.every(frame_every, "write_frames", [&] { out.write_frame(r, ctx, frame); });
  common::Progress progress("tube-cell", max_steps, ctx.show_progress() && !request.quiet);
  const SampledRunHooks hooks{
      .sample =
          [&] {
            const double n = static_cast<double>(std::max(1L, summed));
            Vec3 f_N;
            for (int a = 0; a < 3; ++a) f_N[a] = r.units.to_si_force(force_sum_lu[a] / n);
            const double t_s = r.units.to_si_time(static_cast<double>(loop.step()));
            const TubeCellSample s = sample_state(r, t_s, f_N, traction_sum_N / n);
            series.add(s);
            out.row(series.row(s));
            force_sum_lu = {};
            traction_sum_N = {};
            summed = 0;
          },
      // Settling is judged on every sample while the series is short, then on every 1 % of its length: the period
      // detection is O(n^2), and runs past the membrane transient reach 10^4 samples. Deterministic in n, so a resumed
      // run stops where an uninterrupted one does.
      .done =
          [&] {
            const std::size_t n = series.size();
            return n % std::max<std::size_t>(1, n / 100) == 0 && series.settled();
          },
      .pack = [&] { return series.pack(); }};
  const bool settled = run_sampled(loop, r, ctx, c.sample_every_steps, c.checkpoint_every_wall_s, progress, hooks, frame);
  out.write_frame(r, ctx, frame);
  ctx.log().info("{} after {} steps ({:.4g} s simulated); wall time per stage:\n{}",
                 settled ? "settled" : "stopped at max_time_s (NOT settled)", loop.step(),
                 r.units.to_si_time(static_cast<double>(loop.step())), loop.timing_table());
  const double simulated_s = r.units.to_si_time(static_cast<double>(loop.step()));
  nlohmann::json summary;
  summary["results"] = series.results();
  summary["results"]["settled"] = settled;
  summary["results"]["setup"] = c.setup == TubeCellSetup::drag ? "drag" : "lift";
  summary["groups"] = groups_of(summary["results"]);
  summary["groups"]["cell_stokes_number"] = cell_stokes_number(c, r.membrane->rest_volume_m3());
  summary["numerics"] = {{"dx_m", c.dx_m},
                         {"dt_s", c.dt_s},
                         {"tau", c.collision.tau},
                         // The lattice fluid's memory against the flow's time at the wall, where the shear is largest:
                         // gamma_wall (tau - 1/2) dt (docs/resolved-coupling.md, "The lattice fluid's memory"). The
                         // cytoplasm's is viscosity_ratio times this at the same shear rate.
                         {"lattice_weissenberg", common::poiseuille_shear_rate(c.u_max_m_s, c.radius_m, c.radius_m) *
                                                     (c.collision.tau - 0.5) * c.dt_s},
                         {"viscosity_ratio", c.viscosity_ratio},   // cytoplasm / plasma; 1: one fluid
                         {"tau_cytoplasm", c.viscosity_ratio != 1.0 ? c.inner_collision.tau : c.collision.tau},
                         {"cytoplasm_nodes", r.cytoplasm ? static_cast<long>(r.cytoplasm->inner_nodes()) : 0L},
                         {"membrane_mass_factor", c.membrane_mass_factor},
                         {"membrane_velocity_relaxation", r.membrane->velocity_relaxation()},   // C_alpha per npFEM step
                         {"spin_up_steps", c.spin_up_steps},
                         {"steps", loop.step()},
                         {"simulated_time_s", simulated_s},
                         {"wall_s_per_simulated_ms", ctx.wall_seconds() / (1e3 * simulated_s)},
                         {"membrane_unconverged_steps", r.membrane->statistics().unconverged_steps},
                         {"membrane_solve", membrane_solve_summary(r.membrane->statistics())}};
  summary["timings"] = loop.timings();
  // The case's check: the forces settle (constant, or periodic for settle_periods) before max_time_s. A --quick run
  // stops after a few samples, too early to settle: it says so instead of failing (the one rule, docs/outputs.md).
  common::CheckList checks;
  if (settled || !request.quick) {
    checks.expect("the forces settle before max_time_s", settled,
                  fmt::format("{} samples, {:.4g} s simulated of max_time_s {:.4g}", series.size(),
                              simulated_s, c.max_time_s));
  } else {
    checks.skip("the forces settle before max_time_s",
                fmt::format("--quick: {} samples, too few to settle", series.size()));
  }
  ctx.write_summary(summary, checks);
  print_result(ctx.log(), summary["results"], c.setup == TubeCellSetup::drag, settled);
  checks.print(ctx.log(), "tube-cell");
  return checks.exit_code();
}

}  // namespace hs::resolved
