// SPDX-License-Identifier: MIT
// The tube-cell case: one RBC in the periodic campaign tube, drag (centre fixed) or lift (axial motion only).
#include "resolved/cases/tube_cell.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "common/check_list.hpp"
#include "common/dimensionless_groups.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/io/atomic_file.hpp"
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
  // The disc axis turned from z to y, the vorticity at the cell: the disc lies in the shear plane of the flow (z) and the
  // radial direction (x), a rolling start that the mirror symmetry y -> -y keeps. disc_tilt_deg turns the normal about
  // x toward the flow, out of that symmetry, to see which motion the cell chooses.
  add_coupled_cell(r, cell_mesh_tilted_from_y(c.membrane, c.disc_tilt_rad), c.membrane, numerics_of(c),
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
  // Poiseuille flow along z turns about the azimuthal direction z x e_r (on the axis: the x-z plane's normal, y).
  s.normal_to_vorticity_rad = normal_to_vorticity_angle(shape, {-radial.y, radial.x, 0.0});
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

/// What one stage of a run leaves: its series' results, whether it settled, and its numerics block.
struct StageOutcome {
  nlohmann::json results;
  bool settled = false;
  std::size_t samples = 0;
  double simulated_s = 0.0;
  nlohmann::json numerics;
};

/// Stage 1 is the case as given; stage 2, with extrapolate_lattice_memory, the same case at half the time step.
constexpr int kHalfTimeStepStage = 2;
/// Stage 1's outcome and final membrane, kept in the run folder when stage 2 follows (resume starts stage 2 from it).
constexpr const char* kStageOneRecord = "stage1.json";

nlohmann::json stage_numerics(const TubeCellRun& r, const common::TimeLoop& loop) {
  const TubeCellConfig& c = r.c;
  const double simulated_s = r.units.to_si_time(static_cast<double>(loop.step()));
  return {{"dx_m", c.dx_m},
          {"dt_s", c.dt_s},
          {"tau", c.collision.tau},
          // The lattice fluid's memory against the flow's time at the wall, where the shear is largest:
          // gamma_wall (tau - 1/2) dt (docs/resolved-coupling.md, "The lattice fluid's memory"). The
          // cytoplasm's is viscosity_ratio times this at the same shear rate.
          {"lattice_weissenberg", common::poiseuille_shear_rate(c.u_max_m_s, c.radius_m, c.radius_m) *
                                      (c.collision.tau - 0.5) * c.dt_s},
          {"viscosity_ratio", c.viscosity_ratio},   // cytoplasm / plasma; 1: one fluid
          {"tau_cytoplasm", c.viscosity_ratio != 1.0 ? c.inner_collision.tau : c.collision.tau},
          // (tau+ - 1/2)(tau- - 1/2) outside and in: the IBM's slip grows with it (collision_params.hpp)
          {"lambda", c.collision.bulk_lambda()},
          {"lambda_cytoplasm", c.viscosity_ratio != 1.0 ? c.inner_collision.bulk_lambda() : c.collision.bulk_lambda()},
          {"cytoplasm_nodes", r.cytoplasm ? static_cast<long>(r.cytoplasm->inner_nodes()) : 0L},
          {"membrane_mass_factor", c.membrane_mass_factor},
          {"membrane_velocity_relaxation", r.membrane->velocity_relaxation()},   // C_alpha per npFEM step
          {"spin_up_steps", c.spin_up_steps},
          {"steps", loop.step()},
          {"simulated_time_s", simulated_s},
          {"wall_s_per_simulated_ms", loop.wall_s_per_simulated_ms(c.dt_s)},
          {"membrane_unconverged_steps", r.membrane->statistics().unconverged_steps},
          {"membrane_solve", membrane_solve_summary(r.membrane->statistics())}};
}

/// Runs one stage to its cap or until it settles: from the checkpoint with `resume`, else from the state `r` was built
/// (or seeded) with. Stage 1 writes timeseries.csv and the ParaView series; stage 2 timeseries_half_dt.csv.
StageOutcome run_stage(TubeCellRun& r, const common::CaseRequest& request, common::RunContext& ctx, int stage, bool resume) {
  const TubeCellConfig& c = r.c;
  TubeCellSeries series(c, r.membrane->rest_volume_m3());
  int frame = 0;
  long first_step = 0;
  if (resume) {
    std::vector<double> packed;
    first_step = read_cell_checkpoint(r, packed, ctx, frame);
    series.unpack(packed);
    ctx.log().info("resumed {}at step {} with {} samples", stage == 1 ? "" : "stage 2 ", first_step, series.size());
  }
  const bool first = stage == 1;
  const CellOutputs out = open_cell_outputs(ctx, tube_cell_columns(), first ? "timeseries.csv" : "timeseries_half_dt.csv", first);
  for (const auto& s : series.samples()) out.row(series.row(s));   // rows up to the checkpoint (resume)
  const long max_steps = r.units.to_lattice_steps(c.max_time_s);
  const long frame_every = first && c.vtk_every_s > 0.0 ? r.units.to_lattice_steps(c.vtk_every_s) : 0;
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
  common::Progress progress(first ? "tube-cell" : "tube-cell, half dt", max_steps, ctx.show_progress() && !request.quiet);
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
      .pack = [&] { return series.pack(); },
      .checkpoint_stage = stage};
  const bool settled = run_sampled(loop, r, ctx, c.sample_every_steps, c.checkpoint_every_wall_s, progress, hooks, frame);
  if (first) out.write_frame(r, ctx, frame);
  ctx.log().info("{}{} after {} steps ({:.4g} s simulated); wall time per stage:\n{}", stage == 1 ? "" : "stage 2: ",
                 settled ? "settled" : "stopped at max_time_s (NOT settled)", loop.step(),
                 r.units.to_si_time(static_cast<double>(loop.step())), loop.timing_table());
  StageOutcome o;
  o.results = series.results();
  o.settled = settled;
  o.samples = series.size();
  o.simulated_s = r.units.to_si_time(static_cast<double>(loop.step()));
  o.numerics = stage_numerics(r, loop);
  o.numerics["timings"] = loop.timings();
  return o;
}

/// Stage 2 starts from stage 1's membrane (positions; velocities zero, as its fluid starts at rest): the markers follow.
void seed_membrane(TubeCellRun& r, const std::vector<double>& stage_one_membrane) {
  const std::size_t n = static_cast<std::size_t>(r.membrane->vertex_count());
  std::vector<double> state(stage_one_membrane.begin(), stage_one_membrane.begin() + static_cast<std::ptrdiff_t>(9 * n + 3));
  std::fill(state.begin() + static_cast<std::ptrdiff_t>(3 * n), state.begin() + static_cast<std::ptrdiff_t>(6 * n), 0.0);
  r.membrane->restore_state(state);   // positions, zero velocities, external forces, centre target; empty solver memory
  CouplingState markers;
  for (const Vec3& x : r.membrane->positions_m()) {
    markers.marker_x_lu.push_back((x - r.origin_m) / r.c.dx_m);
    markers.marker_u_lu.push_back({});
  }
  r.cell->restore(markers);
  update_cytoplasm(r);
}

void print_stage(common::Log& log, const TubeCellConfig& c, const TubeCellRun& r, int stage) {
  log.info("tube-cell ({}){}: r* = {}, Re = {}, U_max = {:.4g} m/s, lattice {}x{}x{}, dx = {:g} m, dt = {:.4g} s, "
           "tau = {:.3f}, peak lattice velocity {:.4g}, membrane every {} steps, viscosity ratio {:.4g} "
           "(cytoplasm tau {:.3f}){}",
           c.setup == TubeCellSetup::drag ? "drag" : "lift", stage == 1 ? "" : ", stage 2 at half the time step",
           c.radial_position, c.reynolds, c.u_max_m_s, r.nodes[0], r.nodes[1], r.nodes[2], c.dx_m, c.dt_s,
           c.collision.tau, c.lattice_velocity, c.membrane_every, c.viscosity_ratio,
           c.viscosity_ratio != 1.0 ? c.inner_collision.tau : c.collision.tau,
           c.disc_tilt_rad != 0.0 ? fmt::format(", disc tilted {:g} deg from the vorticity", c.disc_tilt_rad * 180.0 / std::numbers::pi) : "");
}

/// Replaces the period means with their values at lattice Weissenberg number 0 (linear through the two stages) and
/// keeps both stages' values under results.lattice_memory.
void extrapolate_results(nlohmann::json& results, const StageOutcome& one, const StageOutcome& two) {
  const double wi_1 = one.numerics["lattice_weissenberg"].get<double>();
  const double wi_2 = two.numerics["lattice_weissenberg"].get<double>();
  nlohmann::json memory = {{"lattice_weissenberg", {wi_1, wi_2}}, {"stage2_settled", two.settled},
                           {"stage2_samples", two.samples}, {"stage2_periods_averaged", two.results.value("periods_averaged", 0)}};
  for (const char* q : {"cd", "cl", "di"}) {
    const std::string mean = std::string(q) + "_mean";
    const std::string spread = std::string(q) + "_spread";
    const double v1 = one.results.value(mean, std::nan(""));
    const double v2 = two.results.value(mean, std::nan(""));
    memory[q] = {v1, v2};
    results[mean] = extrapolated_to_zero_weissenberg(v1, wi_1, v2, wi_2);
    // Error propagation of the linear extrapolation: |d Q0 / d Q2| = wi_1 / (wi_1 - wi_2), |d Q0 / d Q1| = wi_2 / (...).
    const double w = wi_1 - wi_2;
    results[spread] = wi_1 / w * two.results.value(spread, 0.0) + wi_2 / w * one.results.value(spread, 0.0);
  }
  memory["note"] = "cd/cl/di_mean are the values at Wi -> 0, linear in Wi through stage 1 and stage 2 (half dt)";
  results["lattice_memory"] = memory;
}

}  // namespace

int run_tube_cell(const common::CaseRequest& request) {
  const TubeCellConfig c = read_tube_cell(*request.config, request.quick);
  require_lattice_memory(*request.config, lattice_nodes(c),
                         {{"[geometry] radius_m", c.radius_m, true}, {"[geometry] length_m", c.length_m, true},
                          {"[numerics] dx_m", c.dx_m, true}});
  common::RunContext ctx = common::RunContext::start(request, "tube-cell");
  // A resumed run whose stage 1 had finished continues with stage 2 (from its checkpoint, or from stage 1's membrane).
  const std::filesystem::path record_file = ctx.folder().file(kStageOneRecord);
  const bool stage_one_done = c.extrapolate_lattice_memory && ctx.resuming() && std::filesystem::exists(record_file);
  StageOutcome one;
  std::vector<double> stage_one_membrane;
  nlohmann::json cell_stokes;
  if (!stage_one_done) {
    auto run = build(c);
    if (ctx.rank() == 0) run->units.write(ctx.folder().file("units.txt"));
    print_stage(ctx.log(), c, *run, 1);
    if (const std::string w = kernel_width_warning(numerics_of(c).ibm.kernel, c.dx_m); !w.empty()) ctx.log().warning("{}", w);
    one = run_stage(*run, request, ctx, 1, ctx.resuming());
    one.numerics["cell_stokes_number"] = cell_stokes_number(c, run->membrane->rest_volume_m3());
    stage_one_membrane = run->membrane->state();
    if (c.extrapolate_lattice_memory && ctx.rank() == 0) {
      const nlohmann::json record = {{"results", one.results}, {"settled", one.settled}, {"samples", one.samples},
                                     {"simulated_s", one.simulated_s}, {"numerics", one.numerics},
                                     {"membrane_state", stage_one_membrane}};
      common::write_file_atomic(record_file, record.dump());
    }
  } else {
    std::ifstream in(record_file);
    const nlohmann::json record = nlohmann::json::parse(in);
    one.results = record["results"];
    one.settled = record["settled"].get<bool>();
    one.samples = record["samples"].get<std::size_t>();
    one.simulated_s = record["simulated_s"].get<double>();
    one.numerics = record["numerics"];
    stage_one_membrane = record["membrane_state"].get<std::vector<double>>();
    ctx.log().info("stage 1 finished before the interruption ({}); continuing with stage 2", kStageOneRecord);
  }
  StageOutcome two;
  if (c.extrapolate_lattice_memory) {
    TubeCellConfig h = half_time_step_stage(c);
    // Stage 1 steady (not periodic) and settled: no tumble to rule out, so stage 2's steady window is the spin-up's.
    h.starts_steady = one.settled && one.results.value("steady", false) && !one.results.value("periodic", false);
    auto run = build(h);
    print_stage(ctx.log(), h, *run, kHalfTimeStepStage);
    const bool resume_two = stage_one_done && checkpoint_stage(ctx) == kHalfTimeStepStage;
    if (!resume_two) seed_membrane(*run, stage_one_membrane);
    two = run_stage(*run, request, ctx, kHalfTimeStepStage, resume_two);
  }
  nlohmann::json summary;
  summary["results"] = one.results;
  const bool settled = one.settled && (!c.extrapolate_lattice_memory || two.settled);
  if (c.extrapolate_lattice_memory) extrapolate_results(summary["results"], one, two);
  summary["results"]["settled"] = settled;
  summary["results"]["setup"] = c.setup == TubeCellSetup::drag ? "drag" : "lift";
  summary["groups"] = groups_of(summary["results"]);
  summary["groups"]["cell_stokes_number"] = one.numerics["cell_stokes_number"];
  summary["timings"] = one.numerics["timings"];
  summary["numerics"] = one.numerics;
  summary["numerics"].erase("timings");
  summary["numerics"].erase("cell_stokes_number");
  if (c.extrapolate_lattice_memory) {
    summary["numerics"]["half_time_step_stage"] = two.numerics;
    summary["numerics"]["half_time_step_stage"].erase("timings");
  }
  // The case's check: the forces settle (constant, or periodic for settle_periods) before max_time_s. A --quick run
  // stops after a few samples, too early to settle: it says so instead of failing (the one rule, docs/outputs.md).
  common::CheckList checks;
  const auto expect_settled = [&](const std::string& what, const StageOutcome& o, double cap_s) {
    if (o.settled || !request.quick) {
      checks.expect(what, o.settled, fmt::format("{} samples, {:.4g} s simulated of max_time_s {:.4g}", o.samples,
                                                 o.simulated_s, cap_s));
    } else {
      checks.skip(what, fmt::format("--quick: {} samples, too few to settle", o.samples));
    }
  };
  expect_settled("the forces settle before max_time_s", one, c.max_time_s);
  if (c.extrapolate_lattice_memory) {
    expect_settled("the half-time-step stage settles (lattice-memory extrapolation)", two, half_time_step_stage(c).max_time_s);
  }
  expect_membrane_converged(checks, one.numerics["membrane_solve"], request.quick,
                            c.extrapolate_lattice_memory ? "stage 1" : "");
  if (c.extrapolate_lattice_memory) {
    expect_membrane_converged(checks, two.numerics["membrane_solve"], request.quick, "half-time-step stage");
  }
  ctx.write_summary(summary, checks);
  print_result(ctx.log(), summary["results"], c.setup == TubeCellSetup::drag, settled);
  checks.print(ctx.log(), "tube-cell");
  return checks.exit_code();
}

}  // namespace hs::resolved
