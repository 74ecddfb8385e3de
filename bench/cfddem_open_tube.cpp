// SPDX-License-Identifier: MIT
// The open tube of `hemoscale bench cfddem`: tube-open's solvers and measurement (OpeningTraffic: CellInjector at
// the inlet, removal at the outlet) on the CFD-DEM skeleton, started full, timed per CFD step.
#include "bench/cfddem_open_tube.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/clean_child.hpp"
#include "common/peak_memory.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/tube_open.hpp"
#include "unresolved/cases/open_geometry_measurement.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/insertion.hpp"

namespace hs::bench {
namespace {

using namespace hs::unresolved;
using Clock = std::chrono::steady_clock;

// The periodic tube's conditions (cfddem_bench.cpp), so the two compare: a 100 um tube, 10 cells across, plasma at
// a mean 1 mm/s, Ht 0.10, dt_CFD = 2e-4 s, the soft contact modulus of tube-pries, Schiller-Naumann drag only.
constexpr double diameter_m = 100e-6;
constexpr int cells_across = 10;
constexpr double hematocrit = 0.10;         // the inflow's discharge Ht_d and the fill's tube Ht
constexpr double mean_velocity_m_s = 1e-3;
constexpr double dt_s = 2e-4;
// Warm-up: the plasma profile develops in R^2 / nu = 2 ms (10 steps); cells placed at least r = 2.8 um from the
// outlet face need > 7 steps at the centreline's 0.4 um per step before the first is removed. After 20 steps both
// the injection and the removal are running (counted in the JSON for the timed steps).
constexpr int warmup_steps = 20;

TubeOpenConfig open_tube_config(long n_cells, int steps) {
  TubeOpenConfig c{};
  c.diameter_m = diameter_m;
  c.cells_across = cells_across;
  c.fluid = {.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6};   // plasma, as the periodic tube
  c.inlet_mean_velocity_m_s = mean_velocity_m_s;
  c.discharge_hematocrit = hematocrit;
  c.seed = 1;
  c.particles = default_particle_params();
  c.particles.particle.youngs_modulus_Pa = 1e3;   // as tube-pries and tube-open
  c.particles.wall.youngs_modulus_Pa = 1e3;
  c.model.drag = closure_spec_from("schiller_naumann");
  c.model.lift = closure_spec_from("none");          // parse_coupling_model's defaults for a case without them
  c.model.deformation = closure_spec_from("none");
  const double dx = diameter_m / cells_across;
  const double area_m2 = std::numbers::pi * 0.25 * diameter_m * diameter_m;
  c.length_m = dx * std::ceil(static_cast<double>(n_cells) * c.particles.volume_m3() / (hematocrit * area_m2) / dx);
  c.dt_s = dt_s;
  c.piso_correctors = 4;   // tube-open's default (tube_open.cpp: two let an odd-even mode grow in the open tube)
  const double limit = 0.1 * std::min(rayleigh_time_s(c.particles),
                                      hertz_time_s(c.particles, c.particles.max_impact_velocity_m_s));
  c.n_coupling = static_cast<int>(std::ceil(dt_s / (0.9 * limit)));   // as the periodic tube
  c.end_time_s = steps * dt_s;
  c.checkpoint_every_wall_s = 1e9;   // no restart folder: never written
  return c;
}

std::size_t column(const std::vector<std::string>& columns, const std::string& name) {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::logic_error("bench cfddem: tube-open has no column " + name);
  return static_cast<std::size_t>(it - columns.begin());
}

}  // namespace

nlohmann::json open_tube_setup_json() {
  return {{"diameter_m", diameter_m}, {"cells_across_diameter", cells_across}, {"hematocrit", hematocrit},
          {"inlet_mean_velocity_m_s", mean_velocity_m_s}, {"dt_cfd_s", dt_s}, {"piso_correctors", 4},
          {"warmup_steps", warmup_steps}, {"drag", "schiller_naumann"},
          {"inlet", "velocity, parabolic, z = 0"}, {"outlet", "pressure, z = L"},
          {"start", "filled by volume insertion at the tube hematocrit"},
          {"process", "each size in a child process of its own (peak_rss_GiB is that size's VmHWM)"}};
}

nlohmann::json measure_open_tube(long n_cells, int repetitions) {
  const auto t_setup = Clock::now();
  const TubeOpenConfig c = open_tube_config(n_cells, warmup_steps + repetitions);
  CfdDemSolvers run(tube_open_setup(c));
  const InsertionResult fill = insert_at_volume_fraction(
      run.shape(), run.dem().domain(), {.volume_fraction = hematocrit, .radius_m = c.particles.radius_m(), .seed = 1});
  for (const auto& x : fill.positions_m) run.dem().add_particle(x);   // inlet_opening -1: placed, not injected
  OpenGeometryMeasurement m(open_geometry_of(c), "tube-open");
  const std::vector<std::string> columns = m.columns();
  std::vector<std::vector<double>> rows;
  std::vector<Clock::time_point> ends;   // wall clock at the end of each CFD step
  const double setup_s = std::chrono::duration<double>(Clock::now() - t_setup).count();
  const CfdDemOutcome out = run_cfd_dem(
      run, m, {.steps = c.steps(), .checkpoint_every_wall_s = c.checkpoint_every_wall_s, .restart = {},
               .on_row = [&rows](const std::vector<double>& row) { rows.push_back(row); },
               .after_step = [&ends](const CfdDemSolvers&, long, bool) { ends.push_back(Clock::now()); },
               .progress = nullptr});
  std::vector<double> times;
  for (int k = warmup_steps; k < warmup_steps + repetitions; ++k) {
    const auto k1 = static_cast<std::size_t>(k);
    times.push_back(std::chrono::duration<double>(ends[k1] - ends[k1 - 1]).count());
  }
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  const auto& before = rows[warmup_steps - 1];
  const auto& after = rows.back();
  const auto change = [&](const char* name) {
    return std::lround(after[column(columns, name)] - before[column(columns, name)]);
  };
  return {{"s_per_cfd_step", sorted[sorted.size() / 2]}, {"step_times_s", times}, {"peak_rss_GiB", hs::common::peak_memory_gib()},
          {"cells", static_cast<long>(run.dem().particles().n_owned())}, {"cells_filled", fill.positions_m.size()},
          {"fvm_cells", run.grid().cell_count()}, {"length_m", c.length_m}, {"n_coupling", c.n_coupling},
          {"timed_steps", repetitions}, {"cells_injected_in_timed_steps", change("inlet_cells_in")},
          {"cells_removed_in_timed_steps", change("outlet_cells_out")}, {"setup_s", setup_s},
          {"stage_timings_all_steps", out.summary["timings"]}};
}

nlohmann::json measure_open_tube_in_child(long n_cells) {
  const auto file =
      std::filesystem::temp_directory_path() / fmt::format("hs_bench_open_tube_{}_{}.json", ::getpid(), n_cells);
  const auto t0 = Clock::now();
  if (!run_clean_child({this_executable(), "bench", "cfddem", "--json", file.string()},
                       {fmt::format("{}={}", open_tube_child_env, n_cells)})) {
    throw std::runtime_error(fmt::format("bench cfddem: the open-tube child for {} cells failed", n_cells));
  }
  const double wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  std::filesystem::remove(file);
  j["wall_s"] = wall_s;
  return j;
}

}  // namespace hs::bench
