// SPDX-License-Identifier: MIT
// `hemoscale bench cfddem`: RBC spheres at Ht 0.10 in a periodic 100 um tube whose length holds N cells; median
// wall time of a coupled CFD step (n_coupling DEM steps + coupling + PISO) and the peak RSS. On N MPI ranks the tube
// is on z-slabs (the case skeleton's CfdDemSolvers) and the keys end in "_npN". On one rank, the same sizes again in
// jobs of one and two ranks at one thread each (strong and weak scaling), then the open tube (cfddem_open_tube.cpp)
// at 1e4 and 1e5 cells, each in a child process, under the key "open_tube".
// HS_BENCH_CFDDEM_ARCHIVE=FILE (a JSON this bench wrote) takes the periodic sizes FILE holds from it instead of
// measuring them (a 1e6 size measured alone, at a quiet hour, completes a run; the failure-path test judges a
// committed full run this way).
#include "bench/cfddem_bench.hpp"
#include "bench/bench_targets.hpp"
#include "bench/clean_child.hpp"
#include "bench/cfddem_open_tube.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include "closures/register_builtin.hpp"
#include "common/errors.hpp"
#include "common/geometry/tube.hpp"
#include "common/peak_memory.hpp"
#include "common/run_folder.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
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
// Set to a number of timed CFD steps per periodic size instead of 3 (development: two runs with different counts
// difference away the set-up, e.g. the messages per step under Open MPI's monitoring, bench/results/README.md).
constexpr const char* timed_steps_env = "HS_BENCH_CFDDEM_TIMED_STEPS";
// Set only in the scaling jobs scale_to_two_ranks() starts: measure the sizes, keys suffixed "_npN", nothing else.
constexpr const char* scaling_job_env = "HS_BENCH_CFDDEM_SCALING_JOB";

struct Measured {
  double s_per_cfd_step;                // median over the timed steps of the slowest rank's time
  double peak_rss_gib;                  // summed over the ranks (the job's memory)
  double peak_rss_gib_per_rank;         // the largest rank's
  int n_coupling;
  long cells;
  double mean_substeps;                 // DEM steps per timed CFD step (drag-limited: fewer than n_coupling)
  std::vector<double> stage_seconds;    // summed over the timed steps, in stage_names order
  long amg_setups;                      // BoomerAMG set-ups and reuses over the timed steps
  long amg_reuses;
  double pressure_iterations;           // per timed CFD step: PCG over the PISO correctors
  double momentum_iterations;           // per timed CFD step: BiCGSTAB over the three components
};

// The coupling's four stages, as the case skeleton names them (docs/cfd-dem.md).
const std::vector<std::string> stage_names{"dem_substeps", "particles_to_grid", "fluid_step", "fluid_to_particles"};

/// The job's ranks (MPI_COMM_WORLD): the periodic tube on z-slabs, one per rank; rank 0 prints and writes.
struct Ranks {
  int rank = 0;
  int size = 1;
  [[nodiscard]] bool root() const { return rank == 0; }
};

Ranks world_ranks() {
  Ranks r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &r.size);
  return r;
}

/// The largest of the ranks' values, element by element (a collective step takes as long as its slowest rank).
std::vector<double> max_over_ranks(std::vector<double> v) {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return v;
}

Measured measure(long n_rbc, int repetitions) {
  const double d_tube = 100e-6;
  const double r = 0.5 * d_tube;
  const double dx = d_tube / 10.0;   // the validation's 10 cells across the diameter
  const double ht = 0.10;
  const double length = dx * std::ceil(static_cast<double>(n_rbc) * rbc_volume_m3 / (ht * std::numbers::pi * r * r) / dx);
  const auto tube = std::make_shared<const hs::common::Tube>(
      hs::common::TubeSpec{.start_m = {0, 0, 0}, .end_m = {0, 0, length}, .radius_m = r});
  FvmGridSpec spec{.box_m = {{-r, -r, 0.0}, {r, r, length}}, .dx_m = dx, .sides = {}};
  spec.sides[4].type = SideType::periodic;
  spec.sides[5].type = SideType::periodic;
  const double dt = 2e-4;
  ParticleParams params = default_particle_params();
  params.particle.youngs_modulus_Pa = 1e3;   // as the tube-pries case
  params.wall.youngs_modulus_Pa = 1e3;
  const double limit = 0.1 * std::min(rayleigh_time_s(params), hertz_time_s(params, params.max_impact_velocity_m_s));
  const int n_coupling = static_cast<int>(std::ceil(dt / (0.9 * limit)));
  const Domain domain{.box = {{-r, -r, 0.0}, {r, r, length}}, .periodic = {false, false, true}};
  CouplingClosures closures;
  closures.drag = hs::closures::make_drag_closure({.model = "schiller_naumann", .file = {}});
  CfdDemSetup setup{
      .shape = tube,
      .grid = spec,
      .fluid = {.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6},
      .piso = {.dt_s = dt},
      .drive = {.mode = FlowDrive::Mode::pressure_gradient, .axis = 2,
                .pressure_gradient_Pa_m = -8.0 * 1.23e-3 * 1e-3 / (r * r)},   // plasma mean velocity 1 mm/s
      .dem = {.params = params, .domain = domain, .time_step_s = dt / n_coupling},
      .coupling = {.n_coupling = n_coupling, .void_fraction_rate = false, .tube_radius_m = r},   // as the tube-pries case
      .closures = std::move(closures)};
  CfdDemSolvers run(std::move(setup), MPI_COMM_WORLD);
  // Every rank draws the same cells and keeps those in its slab, with the ids one rank gives them (as tube-pries).
  const InsertionResult ins = insert_at_volume_fraction(*tube, domain, {.volume_fraction = ht, .radius_m = params.radius_m(), .seed = 1});
  for (std::size_t k = 0; k < ins.positions_m.size(); ++k) {
    const hs::common::Vec3& x = ins.positions_m[k];
    const DemSlabs* slabs = run.slabs();
    if (slabs == nullptr || (x.z >= slabs->lo_m() && x.z < slabs->hi_m())) (void)run.dem().add_particle(x, {}, static_cast<std::int64_t>(k));
  }
  CfdDemCoupling& coupling = run.coupling();
  FvmSolver& fluid = run.fluid();
  coupling.set_mean_velocity_m_s(1e-3);
  coupling.step();   // warm-up: list build, AMG set-up
  std::vector<double> times;
  std::vector<double> stages(stage_names.size(), 0.0);
  long substeps = 0;
  long pressure_iterations = 0, momentum_iterations = 0;
  const long setups0 = fluid.pressure_solver().setups(), reuses0 = fluid.pressure_solver().reuses();
  using Clock = std::chrono::steady_clock;
  for (int k = 0; k < repetitions; ++k) {
    MPI_Barrier(MPI_COMM_WORLD);   // every rank starts the step together: its time is the slowest rank's
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
    pressure_iterations += fluid.last_stats().pressure_iterations;
    momentum_iterations += fluid.last_stats().momentum_iterations;
    coupling.fluid_to_particles();
    lap(3);
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    substeps += coupling.last_substeps();
  }
  times = max_over_ranks(times);
  stages = max_over_ranks(stages);
  std::sort(times.begin(), times.end());
  const std::array<int, 3> cells = FvmGrid::cells_of(spec);
  double rss = hs::common::peak_memory_gib(), rss_sum = 0.0, rss_max = 0.0;
  MPI_Allreduce(&rss, &rss_sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&rss, &rss_max, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return {times[times.size() / 2], rss_sum, rss_max, n_coupling, static_cast<long>(cells[0]) * cells[1] * cells[2],
          static_cast<double>(substeps) / repetitions, stages, fluid.pressure_solver().setups() - setups0,
          fluid.pressure_solver().reuses() - reuses0, static_cast<double>(pressure_iterations) / repetitions,
          static_cast<double>(momentum_iterations) / repetitions};
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
  if (file == nullptr || *file == '\0') return nullptr;
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

/// "cfddem_1e6", "cfddem_2e5": the key of a periodic size in the JSON.
std::string size_key(long n) {
  const int exponent = static_cast<int>(std::floor(std::log10(static_cast<double>(n)) + 1e-9));
  const long mantissa = std::lround(static_cast<double>(n) / std::pow(10.0, exponent));
  return fmt::format("cfddem_{}e{}", mantissa, exponent);
}

/// One periodic size on this job's ranks: printed by rank 0, its keys (with `suffix`) into j.
/// The timed CFD steps per periodic size: 3, or timed_steps_env.
int timed_steps() {
  const char* v = std::getenv(timed_steps_env);
  if (v == nullptr || *v == '\0') return 3;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (*end != '\0' || n < 1 || n > 1000) {
    throw hs::common::ConfigError(fmt::format("{}={}: a number of timed CFD steps, 1 to 1000", timed_steps_env, v));
  }
  return static_cast<int>(n);
}

/// One periodic size on this job's ranks: printed by rank 0, its keys (with `suffix`) into j.
void measure_size(long n, const Ranks& ranks, const std::string& suffix, nlohmann::json& j) {
  const int steps = timed_steps();
  const Measured m = measure(n, steps);
  const std::string key = size_key(n);
  if (ranks.root()) {
    fmt::print("  {:>8} RBCs{}: {:.3f} s per CFD step (median of {}, n_coupling = {}, {:.1f} DEM steps per CFD step, {} cells), "
               "peak RSS {:.2f} GiB{}; stages (s, {} steps):", n,
               suffix.empty() ? "" : fmt::format(" on {} rank(s) x {} thread(s)", ranks.size, omp_get_max_threads()),
               m.s_per_cfd_step, steps, m.n_coupling, m.mean_substeps, m.cells, m.peak_rss_gib,
               ranks.size > 1 ? fmt::format(" ({:.2f} the largest rank)", m.peak_rss_gib_per_rank) : "", steps);
    for (std::size_t s = 0; s < stage_names.size(); ++s) fmt::print(" {} {:.3f}", stage_names[s], m.stage_seconds[s]);
    fmt::print("; AMG set-ups {} reuses {}; iterations per step: pressure {:.1f}, momentum {:.1f}\n", m.amg_setups,
               m.amg_reuses, m.pressure_iterations, m.momentum_iterations);
    std::fflush(stdout);
  }
  j[key + "_s_per_cfd_step" + suffix] = m.s_per_cfd_step;
  j[key + "_peak_rss_GiB" + suffix] = m.peak_rss_gib;
  if (ranks.size > 1) j[key + "_peak_rss_GiB_per_rank" + suffix] = m.peak_rss_gib_per_rank;
  j[key + "_dem_steps_per_cfd_step" + suffix] = m.mean_substeps;
  for (std::size_t s = 0; s < stage_names.size(); ++s) j[key + "_stage_s" + suffix][stage_names[s]] = m.stage_seconds[s];
  j[key + "_amg_setups" + suffix] = m.amg_setups;
  j[key + "_amg_reuses" + suffix] = m.amg_reuses;
  j[key + "_pressure_iterations_per_step" + suffix] = m.pressure_iterations;
  j[key + "_momentum_iterations_per_step" + suffix] = m.momentum_iterations;
}

/// `sizes` in a job of `ranks` ranks with one thread each (`mpiexec -n ranks` of this executable, scaling_job_env
/// set): its "_npN" keys merged into j. False (reported) when the job failed.
bool run_scaling_job(int ranks, const std::vector<long>& sizes, nlohmann::json& j) {
  std::string list;
  for (const long n : sizes) list += fmt::format("{}{}", list.empty() ? "" : ",", n);
  fmt::print("cfddem on {} rank(s) x 1 thread (mpiexec -n {}, a job of its own): {} RBCs\n", ranks, ranks, list);
  std::fflush(stdout);
  const auto file = std::filesystem::temp_directory_path() / fmt::format("hs_bench_cfddem_np{}_{}.json", ranks, ::getpid());
  std::vector<std::string> argv{HS_MPIEXEC, "-n", std::to_string(ranks), "--oversubscribe"};
  if (::geteuid() == 0) argv.emplace_back("--allow-run-as-root");   // containers run as root; mpiexec refuses it otherwise
  argv.insert(argv.end(), {this_executable(), "bench", "cfddem", "--json", file.string()});
  bool ran = false;
  try {
    ran = run_clean_child(argv, {fmt::format("{}={}", periodic_sizes_env, list), fmt::format("{}=1", scaling_job_env),
                                 "OMP_NUM_THREADS=1"});
  } catch (const std::exception& e) {   // no mpiexec here: the one-rank numbers still stand
    fmt::print("  {}\n", e.what());
  }
  if (!ran) {
    fmt::print("  the {}-rank job failed: no _np{} keys\n", ranks, ranks);
    j[fmt::format("np{}_failed", ranks)] = true;
    return false;
  }
  const nlohmann::json job = nlohmann::json::parse(std::ifstream(file));
  std::filesystem::remove(file);
  const std::string suffix = fmt::format("_np{}", ranks);
  for (const auto& [name, value] : job.items()) {
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) j[name] = value;
  }
  return true;
}

/// Scaling at one thread per rank, each rank count a job of its own: the sizes measured here on one rank and on
/// two, and each size below 1e6 doubled on two. Strong scaling t_np1 / (2 t_np2) (the same tube), weak scaling
/// t_np1(N) / t_np2(2N) (twice the tube on twice the ranks; 1e6 has no partner: 2e6 cells, ~5 GiB, minutes a step),
/// and the two ranks against this run's one rank with all its threads (the same cores: MPI or OpenMP).
void scale_to_two_ranks(const std::vector<long>& measured, nlohmann::json& j) {
  std::vector<long> doubled = measured;
  for (const long n : measured) {
    if (n < 1000000) doubled.push_back(2 * n);
  }
  std::sort(doubled.begin(), doubled.end());
  j["threads"] = omp_get_max_threads();
  if (!run_scaling_job(1, measured, j) || !run_scaling_job(2, doubled, j)) return;
  for (const long n : measured) {
    const std::string key = size_key(n);
    const double t1 = j[key + "_s_per_cfd_step_np1"].get<double>();
    const double t2 = j[key + "_s_per_cfd_step_np2"].get<double>();
    const double strong = t1 / (2.0 * t2);
    const double vs_threads = j[key + "_s_per_cfd_step"].get<double>() / t2;
    j[key + "_strong_efficiency_np2"] = strong;
    j[key + "_speedup_np2_vs_threads"] = vs_threads;
    fmt::print("  {:>8} RBCs: strong-scaling efficiency on 2 ranks {:.2f} (speed-up {:.2f} over one rank, {:.2f} over one "
               "rank with {} threads)", n, strong, 2.0 * strong, vs_threads, omp_get_max_threads());
    if (n < 1000000) {
      const double weak = t1 / j[size_key(2 * n) + "_s_per_cfd_step_np2"].get<double>();
      j[key + "_weak_efficiency_np2"] = weak;
      fmt::print(", weak-scaling efficiency {:.2f} ({} RBCs on 2 ranks)", weak, 2 * n);
    }
    fmt::print("\n");
  }
}

}  // namespace

int run_cfddem_bench(const hs::common::TaskOptions& options) {
  if (const char* cells = std::getenv(open_tube_child_env)) {   // a child of open_tube_sizes(): one size only
    hs::unresolved::require_one_rank("bench cfddem (open tube)");
    const nlohmann::json m = measure_open_tube(std::stol(cells), open_tube_repetitions);
    if (options.json_file) hs::common::write_json(*options.json_file, m);
    return 0;
  }
  const Ranks ranks = world_ranks();
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
  const bool job = std::getenv(scaling_job_env) != nullptr;   // a scaling job: its sizes, "_npN" keys, no more
  const nlohmann::json archive = job ? nlohmann::json(nullptr) : read_archive();
  nlohmann::json j;
  if (!archive.is_null()) j["archive"] = archive["file"];
  j["mpi_ranks"] = ranks.size;
  if (ranks.root() && !job) fmt::print("cfddem: RBC spheres at Ht 0.10 in a periodic 100 um tube, 10 cells across, dt_CFD = 2e-4 s\n");
  std::vector<long> measured;
  for (const long n : sizes) {
    if (copy_archived_size(archive, size_key(n), j)) continue;
    measure_size(n, ranks, job || ranks.size > 1 ? fmt::format("_np{}", ranks.size) : "", j);
    measured.push_back(n);
  }
  if (job || ranks.size > 1) {   // the targets are judged on one rank's keys, by the one-rank run (which scales too)
    j["provenance"] = hs::common::provenance();
    if (ranks.root() && options.json_file) hs::common::write_json(*options.json_file, j);
    return 0;
  }
  // One rank: scaling jobs of the same sizes, then the open tube, each in processes of their own.
  if (!measured.empty()) scale_to_two_ranks(measured, j);
  if (only == nullptr) j["open_tube"] = open_tube_sizes(options.quick);
  hs::common::CheckList checks;
  const auto measured_key = [&j](const char* key) { return j.contains(key) ? std::optional<double>(j[key].get<double>()) : std::nullopt; };
  expect_at_most(checks, options, "cfddem_1e6_s_per_cfd_step", measured_key("cfddem_1e6_s_per_cfd_step"), 2.0,
                 "issue #28: <= 2 s per CFD step at 1e6 RBCs on this 2-core machine");
  expect_at_most(checks, options, "cfddem_1e6_peak_rss_GiB", measured_key("cfddem_1e6_peak_rss_GiB"), 4.0,
                 "issue #28: peak memory <= 4 GiB at 1e6 RBCs");
  checks.write_to(j);
  j["provenance"] = hs::common::provenance();
  if (options.json_file) hs::common::write_json(*options.json_file, j);
  checks.print("bench cfddem");
  return checks.exit_code();
}

}  // namespace hs::bench
