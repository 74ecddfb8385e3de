// SPDX-License-Identifier: MIT
// `hemoscale bench cfddem`: RBC spheres at Ht 0.10 in a periodic 100 um tube whose length holds N cells; median
// wall time of a coupled CFD step (n_coupling DEM steps + coupling + PISO) and the process's peak RSS. Then the open
// tube (cfddem_open_tube.cpp) at 1e4 and 1e5 cells, each in a child process, under the key "open_tube".
// HS_BENCH_CFDDEM_ARCHIVE=FILE (a JSON this bench wrote) takes the periodic sizes FILE holds from it instead of
// measuring them (a 1e6 size measured alone, at a quiet hour, completes a run; the failure-path test judges a
// committed full run this way).
#include "bench/cfddem_bench.hpp"
#include "bench/bench_targets.hpp"
#include "bench/cfddem_open_tube.hpp"
#include "bench/peak_rss.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "closures/register_builtin.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/run_folder.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/coupling/one_rank_guard.hpp"
#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/insertion.hpp"

namespace hs::bench {
namespace {

using namespace hs::unresolved;

constexpr int open_tube_repetitions = 5;   // timed CFD steps per open-tube size (median)
// Set to a comma-separated list of RBC counts (e.g. "100000"): only those periodic sizes, no open tube (profiling
// one size during development; bench/results/README.md).
constexpr const char* periodic_sizes_env = "HS_BENCH_CFDDEM_SIZES";
// Set to a JSON this bench wrote: its periodic sizes are taken from it, not measured (see the file comment).
constexpr const char* archive_env = "HS_BENCH_CFDDEM_ARCHIVE";

struct Measured {
  double s_per_cfd_step;
  double peak_rss_gib;
  int n_coupling;
  long cells;
  double mean_substeps;                 // DEM steps per timed CFD step (drag-limited: fewer than n_coupling)
  std::vector<double> stage_seconds;    // summed over the timed steps, in stage_names order
  long amg_setups;                      // BoomerAMG set-ups and reuses over the timed steps
  long amg_reuses;
};

// The coupling's four stages, as the case skeleton names them (docs/cfd-dem.md).
const std::vector<std::string> stage_names{"dem_substeps", "particles_to_grid", "fluid_step", "fluid_to_particles"};

Measured measure(long n_rbc, int repetitions) {
  const double d_tube = 100e-6;
  const double r = 0.5 * d_tube;
  const double dx = d_tube / 10.0;   // the validation's 10 cells across the diameter
  const double ht = 0.10;
  const double length = dx * std::ceil(static_cast<double>(n_rbc) * rbc_volume_m3 / (ht * std::numbers::pi * r * r) / dx);
  const hs::common::Tube tube({.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = r});
  FvmGridSpec spec{.box_m = {{-r, -r, 0.0}, {r, r, length}}, .dx_m = dx, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const FvmGrid grid(tube, spec);
  const FluidProperties plasma{.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6};
  const double gradient = -8.0 * 1.23e-3 * 1e-3 / (r * r);   // plasma mean velocity 1 mm/s
  const double dt = 2e-4;
  ParticleParams params = default_particle_params();
  params.particle.youngs_modulus_Pa = 1e3;   // as the tube-pries case
  params.wall.youngs_modulus_Pa = 1e3;
  const double limit = 0.1 * std::min(rayleigh_time_s(params), hertz_time_s(params, params.max_impact_velocity_m_s));
  const int n_coupling = static_cast<int>(std::ceil(dt / (0.9 * limit)));
  const Domain domain{.box = {{-r, -r, 0.0}, {r, r, length}}, .periodic = {false, false, true}};
  const InsertionResult ins = insert_at_volume_fraction(tube, domain, {.volume_fraction = ht, .radius_m = params.radius_m(), .seed = 1});
  DemSystem dem({.params = params, .domain = domain, .time_step_s = dt / n_coupling}, &tube);
  for (const auto& x : ins.positions_m) dem.add_particle(x);
  FvmSolver fluid(grid, plasma, {.dt_s = dt}, {.mode = FlowDrive::Mode::pressure_gradient, .axis = 2, .pressure_gradient_Pa_m = gradient});
  CouplingClosures closures;
  closures.drag = hs::closures::make_drag_closure({.model = "schiller_naumann", .file = {}});
  CfdDemCoupling coupling(fluid, dem, {.n_coupling = n_coupling, .void_fraction_rate = false, .tube_radius_m = r},
                          std::move(closures));   // as the tube-pries case (see CouplingSettings)
  coupling.set_mean_velocity_m_s(1e-3);
  coupling.step();   // warm-up: list build, AMG set-up
  std::vector<double> times;
  std::vector<double> stages(stage_names.size(), 0.0);
  long substeps = 0;
  const long setups0 = fluid.pressure_solver().setups(), reuses0 = fluid.pressure_solver().reuses();
  using Clock = std::chrono::steady_clock;
  for (int k = 0; k < repetitions; ++k) {
    const auto t0 = Clock::now();
    auto t = t0;
    const auto lap = [&](std::size_t stage) {
      const auto now = Clock::now();
      stages[stage] += std::chrono::duration<double>(now - t).count();
      t = now;
    };
    coupling.dem_substeps();
    lap(0);
    coupling.particles_to_grid();
    lap(1);
    coupling.fluid_step();
    lap(2);
    coupling.fluid_to_particles();
    lap(3);
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    substeps += coupling.last_substeps();
  }
  std::sort(times.begin(), times.end());
  return {times[times.size() / 2], peak_rss_gib(), n_coupling, grid.cell_count(),
          static_cast<double>(substeps) / repetitions, stages, fluid.pressure_solver().setups() - setups0,
          fluid.pressure_solver().reuses() - reuses0};
}

/// The open tube at 1e4 and 1e5 cells (1e4 with --quick), each in a child process; JSON keyed "1e4", "1e5".
nlohmann::json open_tube_sizes(bool quick) {
  nlohmann::json out;
  out["setup"] = open_tube_setup_json();
  const std::vector<long> sizes = quick ? std::vector<long>{10000} : std::vector<long>{10000, 100000};
  fmt::print("cfddem open tube: velocity inlet, pressure outlet, RBCs injected and removed; started full at Ht 0.10, "
             "100 um, 10 cells across, dt_CFD = 2e-4 s, {} warm-up steps\n", out["setup"]["warmup_steps"].get<int>());
  for (const long n : sizes) {
    const nlohmann::json m = measure_open_tube_in_child(n);
    fmt::print("  {:>8} RBCs: {:.3f} s per CFD step (median of {}, n_coupling = {}, {} FVM cells), "
               "peak RSS {:.2f} GiB, {} in / {} out while timed, {:.0f} s wall\n", m["cells"].get<long>(), m["s_per_cfd_step"].get<double>(),
               m["timed_steps"].get<int>(), m["n_coupling"].get<int>(), m["fvm_cells"].get<long>(),
               m["peak_rss_GiB"].get<double>(), m["cells_injected_in_timed_steps"].get<long>(),
               m["cells_removed_in_timed_steps"].get<long>(), m["wall_s"].get<double>());
    out[fmt::format("1e{}", static_cast<int>(std::lround(std::log10(static_cast<double>(n)))))] = m;
  }
  return out;
}

/// An earlier run's JSON (HS_BENCH_CFDDEM_ARCHIVE), or null without the variable.
nlohmann::json read_archive() {
  const char* file = std::getenv(archive_env);
  if (file == nullptr) return nullptr;
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!in || j.is_discarded() || !j.is_object()) {
    throw hs::common::ConfigError(fmt::format("{}={}: not a JSON written by `hemoscale bench cfddem --json`", archive_env, file));
  }
  j["file"] = file;
  return j;
}

/// The keys of one periodic size ("cfddem_1e6") copied from the archive; false when it does not hold that size.
bool copy_archived_size(const nlohmann::json& archive, const std::string& key, nlohmann::json& j) {
  if (archive.is_null() || !archive.contains(key + "_s_per_cfd_step") || !archive.contains(key + "_peak_rss_GiB")) return false;
  for (const auto& [name, value] : archive.items()) {
    if (name.rfind(key + "_", 0) == 0) j[name] = value;
  }
  fmt::print("  {}: {:.3f} s per CFD step, peak RSS {:.2f} GiB, from {} (written {}, commit {}), not measured\n", key,
             archive[key + "_s_per_cfd_step"].get<double>(), archive[key + "_peak_rss_GiB"].get<double>(),
             archive["file"].get<std::string>(),
             archive.value(nlohmann::json::json_pointer("/provenance/written_utc"), std::string("?")),
             archive.value(nlohmann::json::json_pointer("/provenance/git_commit"), std::string("?")));
  j["archived_sizes"].push_back(key);
  return true;
}

}  // namespace

int run_cfddem_bench(const hs::common::TaskOptions& options) {
  hs::unresolved::require_one_rank("bench cfddem");
  if (const char* cells = std::getenv(open_tube_child_env)) {   // a child of open_tube_sizes(): one size only
    const nlohmann::json m = measure_open_tube(std::stol(cells), open_tube_repetitions);
    if (options.json_file) hs::common::write_json(*options.json_file, m);
    return 0;
  }
  std::vector<long> sizes = options.quick ? std::vector<long>{10000} : std::vector<long>{10000, 100000, 1000000};
  const char* only = std::getenv(periodic_sizes_env);   // development: these periodic sizes only, no open tube
  if (only != nullptr) {
    sizes.clear();
    for (std::string rest = only; !rest.empty();) {
      const std::size_t comma = rest.find(',');
      sizes.push_back(std::stol(rest.substr(0, comma)));
      rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    }
  }
  const nlohmann::json archive = read_archive();
  nlohmann::json j;
  if (!archive.is_null()) j["archive"] = archive["file"];
  fmt::print("cfddem: RBC spheres at Ht 0.10 in a periodic 100 um tube, 10 cells across, dt_CFD = 2e-4 s\n");
  for (const long n : sizes) {
    const std::string key = fmt::format("cfddem_1e{}", static_cast<int>(std::lround(std::log10(static_cast<double>(n)))));
    if (copy_archived_size(archive, key, j)) continue;
    const Measured m = measure(n, 3);
    fmt::print("  {:>8} RBCs: {:.3f} s per CFD step (median of 3, n_coupling = {}, {:.1f} DEM steps per CFD step, {} cells), "
               "peak RSS {:.2f} GiB; stages (s, 3 steps):", n, m.s_per_cfd_step, m.n_coupling, m.mean_substeps, m.cells, m.peak_rss_gib);
    for (std::size_t s = 0; s < stage_names.size(); ++s) fmt::print(" {} {:.3f}", stage_names[s], m.stage_seconds[s]);
    fmt::print("; AMG set-ups {} reuses {}\n", m.amg_setups, m.amg_reuses);
    j[key + "_s_per_cfd_step"] = m.s_per_cfd_step;
    j[key + "_peak_rss_GiB"] = m.peak_rss_gib;
    j[key + "_dem_steps_per_cfd_step"] = m.mean_substeps;
    for (std::size_t s = 0; s < stage_names.size(); ++s) j[key + "_stage_s"][stage_names[s]] = m.stage_seconds[s];
    j[key + "_amg_setups"] = m.amg_setups;
    j[key + "_amg_reuses"] = m.amg_reuses;
  }
  if (only == nullptr) j["open_tube"] = open_tube_sizes(options.quick);
  hs::common::CheckList checks;
  const auto measured = [&j](const char* key) { return j.contains(key) ? std::optional<double>(j[key].get<double>()) : std::nullopt; };
  expect_at_most(checks, options, "cfddem_1e6_s_per_cfd_step", measured("cfddem_1e6_s_per_cfd_step"), 2.0,
                 "issue #28: <= 2 s per CFD step at 1e6 RBCs on this 2-core machine");
  expect_at_most(checks, options, "cfddem_1e6_peak_rss_GiB", measured("cfddem_1e6_peak_rss_GiB"), 4.0,
                 "issue #28: peak memory <= 4 GiB at 1e6 RBCs");
  checks.write_to(j);
  j["provenance"] = hs::common::provenance();
  if (options.json_file) hs::common::write_json(*options.json_file, j);
  checks.print("bench cfddem");
  return checks.exit_code();
}

}  // namespace hs::bench
