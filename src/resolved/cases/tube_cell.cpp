// SPDX-License-Identifier: MIT
// The tube-cell case: one RBC in the periodic campaign tube, drag (centre fixed) or lift (axial motion only).
#include "resolved/cases/tube_cell.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/io/checkpoint.hpp"
#include "common/io/csv_writer.hpp"
#include "common/io/vtk_image.hpp"
#include "common/io/vtk_polydata.hpp"
#include "common/parallel/gather.hpp"
#include "common/progress.hpp"
#include "common/run_context.hpp"
#include "common/time_loop.hpp"
#include "common/units/unit_converter.hpp"
#include "resolved/cases/tube_cell_config.hpp"
#include "resolved/cases/tube_cell_series.hpp"
#include "resolved/ibm/coupled_cell.hpp"
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

/// The generated RBC with its disc axis turned from z to y: the disc then lies in the plane of the flow (z) and
/// the radial direction (x), the plane in which it tumbles or tank-treads.
TriangleMesh rotated_cell(const TubeCellConfig& c) {
  TriangleMesh mesh = build_membrane_mesh(c.membrane);
  for (auto& v : mesh.vertices_m) v = {v.x, -v.z, v.y};   // rotation by +90 degrees about x
  return mesh;
}

/// Everything one run holds: lattice, membrane, coupling and outputs.
struct TubeCellRun {
  TubeCellConfig c;
  common::UnitConverter units;
  std::array<int, 3> nodes;
  Vec3 origin_m;
  std::unique_ptr<common::Tube> tube;
  std::unique_ptr<FluidLattice> lattice;
  std::unique_ptr<NpfemSolver> membrane;
  std::unique_ptr<CoupledCell> cell;
};

std::unique_ptr<TubeCellRun> build(const TubeCellConfig& c) {
  auto run = std::make_unique<TubeCellRun>(TubeCellRun{
      .c = c, .units = common::UnitConverter(common::LatticeScales{.dx_m = c.dx_m, .dt_s = c.dt_s, .rho_kg_m3 = c.density_kg_m3}),
      .nodes = lattice_nodes(c), .origin_m = {}, .tube = nullptr, .lattice = nullptr, .membrane = nullptr, .cell = nullptr});
  auto& r = *run;
  const double centre_lu = 0.5 * (r.nodes[0] - 1);
  r.origin_m = {-centre_lu * c.dx_m, -centre_lu * c.dx_m, 0.0};
  r.tube = std::make_unique<common::Tube>(common::TubeSpec{
      .start_m = {0.0, 0.0, -c.dx_m}, .end_m = {0.0, 0.0, c.length_m + c.dx_m}, .radius_m = c.radius_m});
  r.lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = r.nodes, .periodic = {false, false, true}, .collision = c.collision}, MPI_COMM_WORLD);
  r.lattice->set_shape(*r.tube, ShapePlacement{.origin = r.origin_m, .spacing = c.dx_m}, c.wall);
  // Poiseuille drive g = 4 nu U_max / R^2 (resolved-methods.md 1.3). The fluid starts at rest: starting from the
  // undisturbed profile stops it impulsively at the cell, whose pressure waves trip the Mach watchdog at
  // lattice_velocity 0.05; spin-up takes a few R^2/nu, a small part of one tumbling period.
  r.lattice->set_body_force({});
  r.lattice->enable_force_field();
  r.lattice->initialize();
  MembraneParameters material = c.membrane.material;
  material.density_kg_m3 *= c.membrane_mass_factor;
  r.membrane = std::make_unique<NpfemSolver>(rotated_cell(c), material, c.membrane.solver,
                                             c.membrane_every * c.dt_s);
  r.membrane->translate_m(Vec3{c.radial_position * c.radius_m, 0.0, 0.5 * c.length_m} - r.membrane->centroid_m());
  r.membrane->set_center_constraint(c.setup == TubeCellSetup::drag ? CenterConstraint::fixed : CenterConstraint::axis,
                                    {0.0, 0.0, 1.0});
  r.cell = std::make_unique<CoupledCell>(*r.lattice, *r.membrane, r.units,
                                         CouplingSettings{.ibm = c.ibm, .membrane_every = c.membrane_every,
                                                          .median_filter = true, .traction_area = c.traction_area,
                                                          .lattice_origin_m = r.origin_m});
  return run;
}

/// Poiseuille drive g = 4 nu U_max / R^2 (resolved-methods.md 1.3), switched on smoothly over spin_up_steps: at
/// large tau the lattice stress lags the forcing by ~tau steps, and a sudden drive overshoots U_max (measured at
/// tau = 60.5: lattice Mach 0.10 after 12 steps, the watchdog stops the run).
double drive_lu(const TubeCellRun& r, long step) {
  const TubeCellConfig& c = r.c;
  const double g_m_s2 = 4.0 * c.kinematic_viscosity_m2_s * c.u_max_m_s / (c.radius_m * c.radius_m);
  const double ramp = static_cast<double>(step) / static_cast<double>(c.spin_up_steps);
  const double share = ramp >= 1.0 ? 1.0 : 0.5 * (1.0 - std::cos(std::numbers::pi * ramp));
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

/// Writes the membrane (.vtp) and, when `fluid`, the lattice (.vti) frames; all ranks call, rank 0 writes.
void write_frames(const TubeCellRun& r, const common::RunContext& ctx, int frame, common::PvdSeries* membrane_pvd,
                  common::PvdSeries* fluid_pvd) {
  const double t = r.units.to_si_time(static_cast<double>(r.lattice->steps_done()));
  std::vector<double> rho, u;
  r.lattice->macroscopic(rho, u);
  const auto rho_all = common::gather_to_root(r.lattice->decomposition(), rho, 1);
  const auto u_all = common::gather_to_root(r.lattice->decomposition(), u, 3);
  if (ctx.rank() != 0) return;
  const auto x = r.membrane->positions_m();
  common::VtkPolyData poly(x, r.membrane->triangles());
  poly.add_point_vector("velocity_m_s", r.membrane->velocities_m_s());
  const std::string mname = fmt::format("membrane_{:05d}.vtp", frame);
  poly.write(ctx.folder().vtk_dir() / mname);
  membrane_pvd->add(t, "vtk/" + mname);
  std::vector<double> pressure(rho_all.size()), velocity(u_all.size());
  for (std::size_t k = 0; k < rho_all.size(); ++k) pressure[k] = r.units.to_si_pressure((rho_all[k] - 1.0) / 3.0);
  for (std::size_t k = 0; k < u_all.size(); ++k) velocity[k] = r.units.to_si_velocity(u_all[k]);
  common::VtkImage image(r.nodes, r.origin_m, r.units.dx_m());
  image.add_vector("velocity_m_s", velocity);
  image.add_scalar("pressure_Pa", pressure, true);
  const std::string fname = fmt::format("fields_{:05d}.vti", frame);
  image.write(ctx.folder().vtk_dir() / fname);
  fluid_pvd->add(t, "vtk/" + fname);
}

std::vector<double> flatten(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::vector<double> out;
  for (const auto* v : {&a, &b}) {
    for (const auto& p : *v) out.insert(out.end(), {p.x, p.y, p.z});
  }
  return out;
}

/// Everything needed to continue bit for bit: populations, force field, membrane, markers, samples (one file per rank).
void write_checkpoint(TubeCellRun& r, const TubeCellSeries& series, const common::RunContext& ctx, long step, int frame) {
  common::Checkpoint cp;
  cp.put("populations", r.lattice->raw_populations());
  const std::span<double> field = r.lattice->force_field();
  cp.put("force_field", std::span<const double>(field.data(), field.size()));
  cp.put("membrane", r.membrane->state());
  const CouplingState st = r.cell->state();
  cp.put("markers", flatten(st.marker_x_lu, st.marker_u_lu));
  cp.put("series", series.pack());
  cp.meta()["step"] = step;
  cp.meta()["coupling_steps"] = st.steps;
  cp.meta()["frame"] = frame;
  cp.write(ctx.folder().checkpoint_dir(), ctx.rank());
}

/// Restores write_checkpoint(); returns the step to continue from.
long read_checkpoint(TubeCellRun& r, TubeCellSeries& series, const common::RunContext& ctx, int& frame) {
  const common::Checkpoint cp = common::Checkpoint::read(ctx.folder().checkpoint_dir(), ctx.rank());
  const long step = cp.meta()["step"].get<long>();
  r.lattice->restore_raw_populations(cp.doubles("populations"), step);
  const auto& field = cp.doubles("force_field");
  const std::span<double> target = r.lattice->force_field();
  if (field.size() != target.size()) throw common::ConfigError("checkpoint: force field of another lattice");
  std::copy(field.begin(), field.end(), target.begin());
  r.membrane->restore_state(cp.doubles("membrane"));
  const auto& m = cp.doubles("markers");
  CouplingState st;
  const std::size_t n = m.size() / 6;
  for (std::size_t k = 0; k < 2 * n; ++k) {
    (k < n ? st.marker_x_lu : st.marker_u_lu).push_back({m[3 * k], m[3 * k + 1], m[3 * k + 2]});
  }
  st.steps = cp.meta()["coupling_steps"].get<long>();
  r.cell->restore(st);
  series.unpack(cp.doubles("series"));
  frame = cp.meta()["frame"].get<int>();
  return step;
}

/// Rank 0's clock decides, so every rank writes the checkpoint of the same step.
bool checkpoint_due(common::CheckpointSchedule& schedule, int rank) {
  int due = rank == 0 && schedule.due() ? 1 : 0;
  MPI_Bcast(&due, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return due != 0;
}

}  // namespace

int run_tube_cell(const common::CaseRequest& request) {
  const TubeCellConfig c = read_tube_cell(*request.config, request.quick);
  common::RunContext ctx = common::RunContext::start(request, "tube-cell");
  auto run = build(c);
  TubeCellRun& r = *run;
  if (ctx.rank() == 0) r.units.write(ctx.folder().file("units.txt"));
  ctx.log().info("tube-cell ({}): r* = {}, Re = {}, U_max = {:.4g} m/s, lattice {}x{}x{}, dx = {:g} m, dt = {:.4g} s, "
                 "tau = {:.3f}, peak lattice velocity {:.4g}, membrane every {} steps",
                 c.setup == TubeCellSetup::drag ? "drag" : "lift", c.radial_position, c.reynolds, c.u_max_m_s,
                 r.nodes[0], r.nodes[1], r.nodes[2], c.dx_m, c.dt_s, c.collision.tau, c.lattice_velocity,
                 c.membrane_every);
  TubeCellSeries series(c, r.membrane->rest_volume_m3());
  int frame = 0;
  const long first_step = ctx.resuming() ? read_checkpoint(r, series, ctx, frame) : 0;
  if (ctx.resuming()) ctx.log().info("resumed at step {} with {} samples", first_step, series.size());
  std::unique_ptr<common::CsvWriter> csv;
  std::unique_ptr<common::PvdSeries> membrane_pvd, fluid_pvd;
  if (ctx.rank() == 0) {
    csv = std::make_unique<common::CsvWriter>(ctx.folder().file("timeseries.csv"), tube_cell_columns());
    for (const auto& s : series.samples()) csv->row(series.row(s));   // rows up to the checkpoint (resume)
    membrane_pvd = std::make_unique<common::PvdSeries>(ctx.folder().file("membrane.pvd"));
    fluid_pvd = std::make_unique<common::PvdSeries>(ctx.folder().file("fields.pvd"));
  }
  const long max_steps = r.units.to_lattice_steps(c.max_time_s);
  const long frame_every = c.vtk_every_s > 0.0 ? r.units.to_lattice_steps(c.vtk_every_s) : 0;
  Vec3 force_sum_lu, traction_sum_N;
  long summed = 0;
  common::TimeLoop loop(max_steps, first_step);
  loop.add("body_force_ramp", [&] { r.lattice->set_body_force({0.0, 0.0, drive_lu(r, loop.step())}); });
  loop.add("membrane_solve", [&] { r.cell->membrane_solve(); });
  loop.add("ibm_forcing", [&] { r.cell->ibm_forcing(); });
  loop.add("lbm_stream_collide", [&] { r.lattice->stream_collide(); });
  loop.add("halo_exchange", [&] { r.lattice->exchange_halos(); });
  loop.add("lbm_boundaries", [&] { r.lattice->apply_boundaries(); });
  loop.add("markers_advect", [&] { r.cell->markers_advect(); });
  loop.add("force_accumulate", [&] {
    force_sum_lu -= r.cell->report().forcing.total_force_lu;   // the force on the cell is minus that on the fluid
    traction_sum_N += r.cell->report().fluid_force_N;
    ++summed;
  });
  loop.every(frame_every, "write_frames", [&] { write_frames(r, ctx, frame++, membrane_pvd.get(), fluid_pvd.get()); });
  common::Progress progress("tube-cell", max_steps, ctx.show_progress() && !request.quiet);
  common::CheckpointSchedule schedule(c.checkpoint_every_wall_s);
  bool settled = series.settled();
  while (!settled && loop.step() < loop.end_step()) {
    loop.run_steps(c.sample_every_steps);
    r.lattice->check_health();
    const double n = static_cast<double>(std::max(1L, summed));
    Vec3 f_N;
    for (int a = 0; a < 3; ++a) f_N[a] = r.units.to_si_force(force_sum_lu[a] / n);
    const TubeCellSample s = sample_state(r, r.units.to_si_time(static_cast<double>(loop.step())), f_N, traction_sum_N / n);
    series.add(s);
    if (csv) csv->row(series.row(s));
    force_sum_lu = {};
    traction_sum_N = {};
    summed = 0;
    settled = series.settled();
    progress.update(loop.step());
    if (checkpoint_due(schedule, ctx.rank())) write_checkpoint(r, series, ctx, loop.step(), frame);
  }
  progress.finish();
  write_checkpoint(r, series, ctx, loop.step(), frame);
  write_frames(r, ctx, frame++, membrane_pvd.get(), fluid_pvd.get());
  ctx.log().info("{} after {} steps ({:.4g} s simulated); wall time per stage:\n{}",
                 settled ? "settled" : "stopped at max_time_s (NOT settled)", loop.step(),
                 r.units.to_si_time(static_cast<double>(loop.step())), loop.timing_table());
  nlohmann::json summary;
  summary["results"] = series.results();
  summary["results"]["settled"] = settled;
  summary["setup"] = c.setup == TubeCellSetup::drag ? "drag" : "lift";
  summary["dx_m"] = c.dx_m;
  summary["dt_s"] = c.dt_s;
  summary["tau"] = c.collision.tau;
  summary["membrane_mass_factor"] = c.membrane_mass_factor;
  summary["cell_stokes_number"] = cell_stokes_number(c, r.membrane->rest_volume_m3());
  summary["spin_up_steps"] = c.spin_up_steps;
  summary["steps"] = loop.step();
  summary["simulated_time_s"] = r.units.to_si_time(static_cast<double>(loop.step()));
  summary["wall_s_per_simulated_ms"] = ctx.wall_seconds() / (1e3 * r.units.to_si_time(static_cast<double>(loop.step())));
  summary["stage_timings"] = loop.timings();
  summary["membrane_unconverged_steps"] = r.membrane->statistics().unconverged_steps;
  ctx.write_summary(summary);
  return settled ? 0 : 1;
}

}  // namespace hs::resolved
