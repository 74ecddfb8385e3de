// SPDX-License-Identifier: MIT
// What every single-RBC coupled case shares: build, stages, frames, checkpoints, the sampled run loop.
#include "resolved/cases/cell_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>
#include <mpi.h>

#include "common/errors.hpp"
#include "common/io/vtk_image.hpp"
#include "common/stop_request.hpp"
#include "common/parallel/gather.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

std::vector<double> flatten(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::vector<double> out;
  for (const auto* v : {&a, &b}) {
    for (const auto& p : *v) out.insert(out.end(), {p.x, p.y, p.z});
  }
  return out;
}

/// What the ranks do after a sample, agreed in one reduction: a periodic checkpoint when rank 0's clock says so (so
/// every rank writes the same step), and a stop when any rank was asked to (its signal, 0 if none).
struct AfterSample {
  bool checkpoint;
  int stop_signal;
};

AfterSample agree_after_sample(common::CheckpointSchedule& schedule, int rank) {
  int v[2] = {rank == 0 && schedule.due() ? 1 : 0, common::stop_signal()};
  MPI_Allreduce(MPI_IN_PLACE, v, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return {v[0] != 0, v[1]};
}

}  // namespace

nlohmann::json groups_of(const nlohmann::json& results) {
  static const char* const kGroups[] = {"reynolds",         "ca",          "ca_open",     "ca_throat",
                                        "ca_initial",       "re_p",        "particle_reynolds",
                                        "particle_reynolds_throat", "gamma_plus", "u_r_plus", "r_star",
                                        "confinement",      "confinement_open", "confinement_throat"};
  nlohmann::json g = nlohmann::json::object();
  for (const char* name : kGroups) {
    if (results.contains(name) && results.at(name).is_number()) g[name] = results.at(name);
  }
  return g;
}

nlohmann::json membrane_solve_summary(const NpfemStatistics& stats) {
  const auto per = [](double a, long b) { return b > 0 ? a / static_cast<double>(b) : 0.0; };
  return {{"steps", stats.steps},
          {"iterations_per_step", per(static_cast<double>(stats.iterations), stats.steps)},
          {"unconverged_steps", stats.unconverged_steps},
          {"line_search_stops", stats.line_search_stops},
          {"iteration_cap_stops", stats.iteration_cap_stops},
          {"unconverged_mean_gradient_over_tolerance", per(stats.unconverged_gradient_sum, stats.unconverged_steps)}};
}

void expect_membrane_converged(common::CheckList& checks, const nlohmann::json& membrane_solve, bool quick,
                               const std::string& label) {
  const std::string what = fmt::format("the membrane solve converges on >= {:.0f} % of its steps{}",
                                       100.0 * kMembraneConvergedShare, label.empty() ? "" : " (" + label + ")");
  const long steps = membrane_solve.at("steps").get<long>();
  if (steps == 0) {
    checks.skip(what, "no membrane step");
    return;
  }
  const long unconverged = membrane_solve.at("unconverged_steps").get<long>();
  const double share = static_cast<double>(unconverged) / static_cast<double>(steps);
  const std::string detail =
      fmt::format("{} of {} steps unconverged ({:.3g} %: {} at the iteration cap, {} in the line search)", unconverged,
                  steps, 100.0 * share, membrane_solve.at("iteration_cap_stops").get<long>(),
                  membrane_solve.at("line_search_stops").get<long>());
  const bool passed = share <= 1.0 - kMembraneConvergedShare;
  if (passed || !quick) {
    checks.expect(what, passed, detail);
  } else {
    checks.skip(what, "--quick: " + detail + ", too few steps past the start to judge a run");
  }
}

TriangleMesh cell_mesh_with_disc_axis(const MembraneConfig& membrane, int axis) {
  TriangleMesh mesh = build_membrane_mesh(membrane);
  for (auto& v : mesh.vertices_m) {
    if (axis == 0) v = {v.z, v.y, -v.x};   // rotation by +90 degrees about y: z -> x
    if (axis == 1) v = {v.x, -v.z, v.y};   // rotation by +90 degrees about x: z -> y
  }
  return mesh;
}

TriangleMesh cell_mesh_tilted_from_y(const MembraneConfig& membrane, double tilt_rad) {
  TriangleMesh mesh = cell_mesh_with_disc_axis(membrane, 1);
  const double c = std::cos(tilt_rad), s = std::sin(tilt_rad);
  for (auto& v : mesh.vertices_m) v = {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
  return mesh;
}

TriangleMesh sphere_cell_mesh(const MembraneConfig& membrane, double radius_m) {
  TriangleMesh sphere = make_sphere_mesh(build_membrane_mesh(membrane).vertex_count());
  const double scale = radius_m / std::cbrt(3.0 * mesh_volume_m3(sphere) / (4.0 * std::numbers::pi));
  for (auto& v : sphere.vertices_m) v = scale * v;
  return sphere;
}

void add_coupled_cell(CellSimulation& s, const TriangleMesh& mesh, const MembraneConfig& membrane, const CellNumerics& n,
                      const Vec3& centroid_m,
                      std::function<void(std::span<const Vec3>, std::vector<Vec3>&)> add_forces_N) {
  MembraneParameters material = membrane.material;
  material.density_kg_m3 *= n.membrane_mass_factor;
  s.membrane = std::make_unique<NpfemSolver>(mesh, material, membrane.solver, n.membrane_every * n.dt_s);
  s.membrane->translate_m(centroid_m - s.membrane->centroid_m());
  s.cell = std::make_unique<CoupledCell>(*s.lattice, *s.membrane, s.units,
                                         CouplingSettings{.ibm = n.ibm, .membrane_every = n.membrane_every,
                                                          .median_filter = true, .membrane_force = n.membrane_force,
                                                          .traction_area = n.traction_area,
                                                          .lattice_origin_m = s.origin_m,
                                                          .drive_on_enclosed_volume = n.drive_on_enclosed_volume,
                                                          .add_forces_N = std::move(add_forces_N)});
  if (n.viscosity_ratio != 1.0) {
    s.lattice->set_inner_collision(n.inner_collision);
    s.cytoplasm = std::make_unique<CytoplasmPhase>(*s.lattice, s.origin_m, s.units.dx_m());
    update_cytoplasm(s);
  }
}

void update_cytoplasm(CellSimulation& s) {
  if (s.cytoplasm) s.cytoplasm->update(s.cell->marker_positions_m(), s.membrane->triangles());
}

void add_coupled_stages(common::TimeLoop& loop, CellSimulation& s) {
  loop.add("membrane_solve", [&s] { s.cell->membrane_solve(); });
  if (s.cytoplasm) {
    loop.add("cytoplasm_indicator", [&s] {
      if (s.cell->interval_starts()) update_cytoplasm(s);
    });
  }
  loop.add("ibm_forcing", [&s] { s.cell->ibm_forcing(); });
  loop.add("lbm_stream_collide", [&s] { s.lattice->stream_collide(); });
  loop.add("halo_exchange", [&s] { s.lattice->exchange_halos(); });
  loop.add("lbm_boundaries", [&s] { s.lattice->apply_boundaries(); });
  loop.add("markers_advect", [&s] { s.cell->markers_advect(); });
}

std::vector<common::Vec3> wrapped_into_box(std::vector<common::Vec3> x_m, const common::Vec3& origin_m,
                                           const std::array<int, 3>& nodes, double dx_m,
                                           const std::array<bool, 3>& periodic) {
  if (x_m.empty()) return x_m;
  common::Vec3 centroid;
  for (const auto& v : x_m) centroid += v;
  centroid = centroid / static_cast<double>(x_m.size());
  for (int a = 0; a < 3; ++a) {
    if (!periodic[a]) continue;
    const double period_m = nodes[a] * dx_m;
    const double shift_m = period_m * std::floor((centroid[a] - origin_m[a]) / period_m);
    for (auto& v : x_m) v[a] -= shift_m;
  }
  return x_m;
}

double smooth_ramp(long step, long steps) {
  if (steps <= 0) return 1.0;
  const double ramp = static_cast<double>(step) / static_cast<double>(steps);
  return ramp >= 1.0 ? 1.0 : 0.5 * (1.0 - std::cos(std::numbers::pi * ramp));
}

void write_cell_frames(const CellSimulation& s, const common::RunContext& ctx, int frame, common::PvdSeries* membrane_pvd,
                       common::PvdSeries* fluid_pvd) {
  const double t = s.units.to_si_time(static_cast<double>(s.lattice->steps_done()));
  std::vector<double> rho, u;
  s.lattice->macroscopic(rho, u);
  const auto rho_all = common::gather_to_root(s.lattice->decomposition(), rho, 1);
  const auto u_all = common::gather_to_root(s.lattice->decomposition(), u, 3);
  if (ctx.rank() != 0) return;
  const auto x = wrapped_into_box(s.membrane->positions_m(), s.origin_m, s.nodes, s.units.dx_m(),
                                  s.lattice->decomposition().periodic());
  common::VtkPolyData poly(x, s.membrane->triangles());
  poly.add_point_vector("velocity_m_s", s.membrane->velocities_m_s());
  const std::string mname = fmt::format("membrane_{:05d}.vtp", frame);
  poly.write(ctx.folder().vtk_dir() / mname);
  membrane_pvd->add(t, "vtk/" + mname);
  if (fluid_pvd == nullptr) return;
  std::vector<double> pressure(rho_all.size()), velocity(u_all.size());
  for (std::size_t k = 0; k < rho_all.size(); ++k) pressure[k] = s.units.to_si_pressure((rho_all[k] - 1.0) / 3.0);
  for (std::size_t k = 0; k < u_all.size(); ++k) velocity[k] = s.units.to_si_velocity(u_all[k]);
  common::VtkImage image(s.nodes, s.origin_m, s.units.dx_m());
  image.add_vector("velocity_m_s", velocity);
  image.add_scalar("pressure_Pa", pressure, true);
  const std::string fname = fmt::format("fields_{:05d}.vti", frame);
  image.write(ctx.folder().vtk_dir() / fname);
  fluid_pvd->add(t, "vtk/" + fname);
}

CellOutputs open_cell_outputs(const common::RunContext& ctx, const std::vector<std::string>& columns,
                              std::string_view series_file, bool frames) {
  CellOutputs out;
  if (ctx.rank() != 0) return out;
  out.csv = std::make_unique<common::CsvWriter>(ctx.folder().file(series_file), columns);
  if (!frames) return out;
  out.membrane_pvd = std::make_unique<common::PvdSeries>(ctx.folder().file("membrane.pvd"));
  out.fluid_pvd = std::make_unique<common::PvdSeries>(ctx.folder().file("fields.pvd"));
  return out;
}

void write_cell_checkpoint(const CellSimulation& s, std::span<const double> samples, const common::RunContext& ctx,
                           long step, int frame, int stage) {
  common::Checkpoint cp;
  cp.put("populations", s.lattice->raw_populations());
  const std::span<double> field = s.lattice->force_field();
  cp.put("force_field", std::span<const double>(field.data(), field.size()));
  cp.put("membrane", s.membrane->state());
  cp.put("membrane_statistics", s.membrane->statistics_state());   // counts and energy books of the whole run
  const CouplingState st = s.cell->state();
  cp.put("markers", flatten(st.marker_x_lu, st.marker_u_lu));
  if (!st.reaction_lu.empty()) cp.put("reaction", flatten(st.reaction_lu, {}));   // ibm_reaction: impulse not yet given
  cp.put("series", samples);
  cp.meta()["step"] = step;
  cp.meta()["coupling_steps"] = st.steps;
  cp.meta()["frame"] = frame;
  cp.meta()["stage"] = stage;
  cp.meta()["streaming"] = s.lattice->streaming() == Streaming::aa ? "aa" : "two_buffer";   // the population layout differs between the two
  cp.write(ctx.folder().checkpoint_dir(), ctx.rank());
}

int checkpoint_stage(const common::RunContext& ctx) {
  return common::Checkpoint::read(ctx.folder().checkpoint_dir(), ctx.rank()).meta().value("stage", 1);
}

long read_cell_checkpoint(CellSimulation& s, std::vector<double>& samples, const common::RunContext& ctx, int& frame) {
  const common::Checkpoint cp = common::Checkpoint::read(ctx.folder().checkpoint_dir(), ctx.rank());
  const long step = cp.meta()["step"].get<long>();
  const std::string written = cp.meta().value("streaming", std::string("two_buffer"));   // older checkpoints: two_buffer
  const std::string running = s.lattice->streaming() == Streaming::aa ? "aa" : "two_buffer";
  if (written != running) {
    throw common::ConfigError(fmt::format("checkpoint in {}: written with [numerics] streaming = \"{}\", the case now "
                                          "says \"{}\"; resume with the setting it was written with",
                                          ctx.folder().checkpoint_dir().string(), written, running));
  }
  s.lattice->restore_raw_populations(cp.doubles("populations"), step);
  const auto& field = cp.doubles("force_field");
  const std::span<double> target = s.lattice->force_field();
  if (field.size() != target.size()) throw common::ConfigError("checkpoint: force field of another lattice");
  std::copy(field.begin(), field.end(), target.begin());
  s.membrane->restore_state(cp.doubles("membrane"));
  if (cp.has("membrane_statistics")) s.membrane->restore_statistics(cp.doubles("membrane_statistics"));   // older: 0
  const auto& m = cp.doubles("markers");
  CouplingState st;
  const std::size_t n = m.size() / 6;
  for (std::size_t k = 0; k < 2 * n; ++k) {
    (k < n ? st.marker_x_lu : st.marker_u_lu).push_back({m[3 * k], m[3 * k + 1], m[3 * k + 2]});
  }
  st.steps = cp.meta()["coupling_steps"].get<long>();
  if (cp.has("reaction")) {
    const auto& r = cp.doubles("reaction");
    for (std::size_t k = 0; k + 2 < r.size(); k += 3) st.reaction_lu.push_back({r[k], r[k + 1], r[k + 2]});
  }
  s.cell->restore(st);
  update_cytoplasm(s);
  const auto& series = cp.doubles("series");
  samples.assign(series.begin(), series.end());
  frame = cp.meta()["frame"].get<int>();
  return step;
}

bool run_sampled(common::TimeLoop& loop, CellSimulation& s, const common::RunContext& ctx, long sample_every_steps,
                 double checkpoint_every_wall_s, common::Progress& progress, const SampledRunHooks& hooks,
                 const int& frame) {
  common::CheckpointSchedule schedule(checkpoint_every_wall_s);
  const common::StopRequestScope stop_requests;
  bool done = hooks.done && hooks.done();
  while (!done && loop.step() < loop.end_step()) {
    loop.run_steps(sample_every_steps);
    s.lattice->check_health();
    hooks.sample();
    done = hooks.done && hooks.done();
    progress.update(loop.step());
    const AfterSample next = agree_after_sample(schedule, ctx.rank());
    if (next.stop_signal != 0) {
      progress.finish();
      write_cell_checkpoint(s, hooks.pack(), ctx, loop.step(), frame, hooks.checkpoint_stage);
      throw common::RunInterrupted(fmt::format("stopped by signal {} at step {} of {}; checkpoint written, continue "
                                               "with --resume", next.stop_signal, loop.step(), loop.end_step()),
                                   next.stop_signal);
    }
    if (next.checkpoint) write_cell_checkpoint(s, hooks.pack(), ctx, loop.step(), frame, hooks.checkpoint_stage);
  }
  progress.finish();
  write_cell_checkpoint(s, hooks.pack(), ctx, loop.step(), frame, hooks.checkpoint_stage);
  return done;
}

}  // namespace hs::resolved
