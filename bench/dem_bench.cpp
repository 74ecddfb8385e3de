// SPDX-License-Identifier: MIT
// `hemoscale bench dem`: 1e5 Hertz spheres packed as in shared/bench/liggghts/in.rbcpack, timed at 1 and 2 threads,
// and LIGGGHTS on the same system in the same invocation when it is on PATH.
#include "bench/dem_bench.hpp"
#include "bench/bench_targets.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/run_folder.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::bench {
namespace {

using hs::unresolved::DemSystem;
using hs::unresolved::ParticleParams;

/// The system of in.rbcpack: nx*ny*nz spheres on a simple-cubic lattice of spacing 0.99 d in a periodic box.
struct PackSpec {
  int nx, ny, nz;
  int settle_steps;   // untimed
  int timed_steps;    // per repetition
};

constexpr int repetitions = 3;
constexpr double jitter_m = 1.5e-7;        // in.rbcpack `jitter`
constexpr double velocity_max_m_s = 5e-3;  // in.rbcpack: components uniform in [-5e-3, 5e-3]
constexpr double time_step_s = 2e-7;       // in.rbcpack `timestep`

ParticleParams rbcpack_params() {
  ParticleParams p = hs::unresolved::default_particle_params();
  p.diameter_m = 7.82e-6;              // d, rho = 1100, E = 1e5, nu = 0.45, e = 0.5, mu = 0.3 as in.rbcpack
  p.skin_m = 7.82e-7;                  // `neighbor 7.82e-7 bin`
  p.max_impact_velocity_m_s = 2.0 * std::sqrt(3.0) * velocity_max_m_s;
  return p;
}

DemSystem make_pack(const PackSpec& s) {
  const ParticleParams p = rbcpack_params();
  const double a = 0.99 * p.diameter_m;
  hs::unresolved::Domain domain{.box = {.lo = {0, 0, 0}, .hi = {s.nx * a, s.ny * a, s.nz * a}}, .periodic = {true, true, true}};
  DemSystem dem({.params = p, .domain = domain, .time_step_s = time_step_s}, nullptr);
  std::mt19937_64 rng(15485863);
  std::uniform_real_distribution<double> jitter(-jitter_m, jitter_m), vel(-velocity_max_m_s, velocity_max_m_s);
  for (int k = 0; k < s.nz; ++k) for (int j = 0; j < s.ny; ++j) for (int i = 0; i < s.nx; ++i) {
    dem.add_particle({i * a + jitter(rng), j * a + jitter(rng), k * a + jitter(rng)}, {vel(rng), vel(rng), vel(rng)});
  }
  return dem;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct DemTiming {
  std::vector<double> ns_per_particle_step;
  double contacts_per_particle = 0.0;
  std::size_t list_builds = 0;
};

DemTiming time_dem(DemSystem& dem, const PackSpec& s, int threads) {
  omp_set_num_threads(threads);
  DemTiming t;
  const double n = static_cast<double>(dem.particles().n_owned());
  for (int rep = 0; rep < repetitions; ++rep) {
    const std::size_t builds_before = dem.stats().list_builds;
    const auto start = std::chrono::steady_clock::now();
    for (int step = 0; step < s.timed_steps; ++step) dem.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.ns_per_particle_step.push_back(seconds * 1e9 / (n * s.timed_steps));
    t.list_builds += dem.stats().list_builds - builds_before;
  }
  t.contacts_per_particle = 2.0 * static_cast<double>(dem.stats().pair_contacts) / n;
  return t;
}

/// shared/bench/liggghts/run_rbcpack.sh, looked for above the executable and the working directory.
std::optional<std::filesystem::path> find_peer_script() {
  const std::filesystem::path rel = "shared/bench/liggghts/run_rbcpack.sh";
  if (const char* env = std::getenv("HS_SHARED_DIR")) {
    if (std::filesystem::exists(std::filesystem::path(env) / "bench/liggghts/run_rbcpack.sh")) {
      return std::filesystem::path(env) / "bench/liggghts/run_rbcpack.sh";
    }
  }
  std::error_code ec;
  for (auto start : {std::filesystem::read_symlink("/proc/self/exe", ec), std::filesystem::current_path()}) {
    for (auto dir = start; !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
      if (std::filesystem::exists(dir / rel)) return dir / rel;
    }
  }
  return std::nullopt;
}

bool on_path(const std::string& program) {
  return std::system(fmt::format("command -v {} > /dev/null 2>&1", program).c_str()) == 0;
}

/// One LIGGGHTS run through the shared script; its "ns/particle-step=" value, or nullopt.
std::optional<double> run_liggghts(const std::filesystem::path& script, const PackSpec& s, int ranks) {
  const auto work = std::filesystem::temp_directory_path() / fmt::format("hs-dem-bench-liggghts-{}", ::getpid());
  // A clean environment: this process may be an MPI singleton whose OMPI_/PMIX_ variables would confuse mpirun.
  const char* path = std::getenv("PATH");
  const std::string cmd = fmt::format("env -i PATH='{}' HOME=/tmp bash '{}' {} {} {} {} {} {} history '{}' 2>&1",
                                      path != nullptr ? path : "/usr/bin:/bin", script.string(), s.nx, s.ny, s.nz, ranks,
                                      s.settle_steps, s.timed_steps, work.string());
  std::string out;
  if (FILE* pipe = ::popen(cmd.c_str(), "r")) {
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), pipe) != nullptr) out += buf.data();
    ::pclose(pipe);
  }
  std::error_code ec;
  std::filesystem::remove_all(work, ec);
  std::smatch m;
  const std::regex re("ns/particle-step=([0-9.eE+-]+)");
  if (std::regex_search(out, m, re)) return std::stod(m[1].str());
  fmt::print("  liggghts np={} gave no result:\n{}\n", ranks, out);
  return std::nullopt;
}

nlohmann::json peer_json(const std::vector<double>& runs) {
  if (runs.empty()) return nullptr;
  return median(runs);
}

}  // namespace

int run_dem_bench(const hs::common::TaskOptions& options) {
  const PackSpec spec = options.quick ? PackSpec{20, 20, 20, 200, 200} : PackSpec{50, 50, 40, 1000, 1000};
  const int max_threads = std::max(2, omp_get_max_threads());
  fmt::print("DEM bench: {} x {} x {} Hertz spheres (in.rbcpack), {} settling + {} x {} timed steps; timings taken "
             "on this machine as it is (not valid under load)\n", spec.nx, spec.ny, spec.nz, spec.settle_steps,
             repetitions, spec.timed_steps);
  std::fflush(stdout);
  DemSystem dem = make_pack(spec);
  omp_set_num_threads(max_threads);
  for (int step = 0; step < spec.settle_steps; ++step) dem.step();
  const DemTiming one = time_dem(dem, spec, 1);
  const DemTiming two = time_dem(dem, spec, 2);
  fmt::print("  hemoscale  1 thread : {:.1f} ns/particle-step (median of {}: {:.1f})\n", median(one.ns_per_particle_step),
             repetitions, fmt::join(one.ns_per_particle_step, ", "));
  fmt::print("  hemoscale  2 threads: {:.1f} ns/particle-step (median of {}: {:.1f})\n", median(two.ns_per_particle_step),
             repetitions, fmt::join(two.ns_per_particle_step, ", "));
  fmt::print("  contacts per particle {:.2f}, neighbour-list builds in the timed runs {}\n", two.contacts_per_particle,
             one.list_builds + two.list_builds);
  std::fflush(stdout);

  std::vector<double> lig1, lig2;
  std::string note;
  const auto script = find_peer_script();
  if (!on_path("liggghts")) {
    note = "liggghts not on PATH: peer not run (install: shared/bench/install_peers.sh)";
  } else if (!script) {
    note = "shared/bench/liggghts/run_rbcpack.sh not found (set HS_SHARED_DIR): peer not run";
  } else {
    for (int rep = 0; rep < repetitions; ++rep) {
      if (auto v = run_liggghts(*script, spec, 1)) lig1.push_back(*v);
      if (auto v = run_liggghts(*script, spec, 2)) lig2.push_back(*v);
    }
    note = fmt::format("liggghts runs via {}", script->string());
  }
  if (!lig1.empty()) fmt::print("  LIGGGHTS   1 rank   : {:.1f} ns/particle-step (median of {})\n", median(lig1), lig1.size());
  if (!lig2.empty()) fmt::print("  LIGGGHTS   2 ranks  : {:.1f} ns/particle-step (median of {})\n", median(lig2), lig2.size());
  if (!lig1.empty()) fmt::print("  speed-up vs LIGGGHTS (1 thread vs 1 rank): {:.2f}x\n", median(lig1) / median(one.ns_per_particle_step));
  fmt::print("  note: {}\n", note);

  hs::common::CheckList checks;
  expect_at_least(checks, options, "speedup_vs_liggghts", lig1.empty() ? std::nullopt : std::optional<double>(median(lig1) / median(one.ns_per_particle_step)),
                  2.0, "issue #28: DEM >= 2x LIGGGHTS per particle-step");
  if (options.json_file) {
    nlohmann::json j;
    j["benchmark"] = "dem";
    j["particles"] = spec.nx * spec.ny * spec.nz;
    j["settle_steps"] = spec.settle_steps;
    j["timed_steps_per_repetition"] = spec.timed_steps;
    j["repetitions"] = repetitions;
    j["dem_ns_per_particle_step"] = median(one.ns_per_particle_step);
    j["dem_ns_per_particle_step_2threads"] = median(two.ns_per_particle_step);
    j["dem_runs_ns_per_particle_step"] = {{"1", one.ns_per_particle_step}, {"2", two.ns_per_particle_step}};
    j["contacts_per_particle"] = two.contacts_per_particle;
    j["liggghts_ns_per_particle_step"] = peer_json(lig1);
    j["liggghts_ns_per_particle_step_2ranks"] = peer_json(lig2);
    j["liggghts_runs_ns_per_particle_step"] = {{"1", lig1}, {"2", lig2}};
    j["speedup_vs_liggghts"] = lig1.empty() ? nlohmann::json(nullptr) : nlohmann::json(median(lig1) / median(one.ns_per_particle_step));
    j["note"] = note;
    j["provenance"] = hs::common::provenance();
    checks.write_to(j);
    hs::common::write_json(*options.json_file, j);
  }
  checks.print("bench dem");
  return checks.exit_code();
}

}  // namespace hs::bench
