// SPDX-License-Identifier: MIT
// `hemoscale bench npfem`: wall time of one npFEM membrane step (and of one quasi-Newton iteration) for one 258- and
// one 642-vertex RBC at the coupled time step (0.25 us, reference §2.3), plus the one-time factorisation cost.
// The cell is loaded like in a flow: 50 pN pulls on its ends, so each step really iterates. Median of 3 repetitions.
// A second 258-vertex run turns the pulls about z once per 100 us (400 steps): a load that never settles, so the
// solver's start predictor cannot profit from a steady state (keys *_258_rotating_load).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/npfem_bench.hpp"
#include "common/case_request.hpp"
#include "common/run_folder.hpp"
#include "resolved/membrane/npfem_solver.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {
namespace {

struct BenchResult {
  double us_per_step;
  double us_per_iteration;
  double iterations_per_step;
  double factorisation_us;
};

constexpr double end_force_N = 50e-12;
constexpr int rotation_period_steps = 400;   // 100 us at h = 0.25 us

/// End loads along (cos a, sin a, 0); a = 0 for the fixed load.
void set_end_loads(NpfemSolver& solver, std::vector<hs::common::Vec3>& f, int lo, int hi, double a) {
  const hs::common::Vec3 pull{end_force_N * std::cos(a), end_force_N * std::sin(a), 0.0};
  f[static_cast<std::size_t>(lo)] = pull * -1.0;
  f[static_cast<std::size_t>(hi)] = pull;
  solver.set_external_forces_N(f);
}

BenchResult bench_one(int vertices, int steps, bool rotating) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = vertices});
  std::vector<hs::common::Vec3> f(mesh.vertices_m.size());
  const auto ends = std::minmax_element(mesh.vertices_m.begin(), mesh.vertices_m.end(),
                                        [](const hs::common::Vec3& a, const hs::common::Vec3& b) { return a.x < b.x; });
  const auto lo = static_cast<int>(ends.first - mesh.vertices_m.begin());
  const auto hi = static_cast<int>(ends.second - mesh.vertices_m.begin());
  std::vector<double> per_step, per_iteration, iterations, factorisation;
  for (int rep = 0; rep < 3; ++rep) {
    NpfemSolver solver(mesh, MembraneParameters{}, NpfemSettings{}, 0.25e-6);
    set_end_loads(solver, f, lo, hi, 0.0);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
      if (rotating) set_end_loads(solver, f, lo, hi, 2.0 * std::numbers::pi * s / rotation_period_steps);
      (void)solver.step();
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    const double its = static_cast<double>(solver.statistics().iterations);
    per_step.push_back(us / steps);
    per_iteration.push_back(its > 0 ? us / its : 0.0);
    iterations.push_back(its / steps);
    factorisation.push_back(solver.statistics().factorisation_s * 1e6);
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  return {median(per_step), median(per_iteration), median(iterations), median(factorisation)};
}

}  // namespace

int bench_npfem(const hs::common::TaskOptions& options) {
  Eigen::setNbThreads(1);   // one core per cell, as in the coupled runs
  const int steps = options.quick ? 100 : 2000;
  nlohmann::json out = {{"benchmark", "npfem"}, {"time_step_s", 0.25e-6}, {"steps", steps}, {"repetitions", 3}};
  for (const int n : {258, 642}) {
    const BenchResult r = bench_one(n, steps, false);
    fmt::print("npfem {:4d} vertices: {:8.1f} us/step, {:6.1f} us/iteration, {:5.2f} iterations/step, "
               "factorisation {:8.1f} us\n", n, r.us_per_step, r.us_per_iteration, r.iterations_per_step, r.factorisation_us);
    out[fmt::format("us_per_step_{}", n)] = r.us_per_step;
    out[fmt::format("us_per_iteration_{}", n)] = r.us_per_iteration;
    out[fmt::format("iterations_per_step_{}", n)] = r.iterations_per_step;
    out[fmt::format("factorisation_us_{}", n)] = r.factorisation_us;
  }
  const BenchResult r = bench_one(258, steps, true);
  fmt::print("npfem  258 vertices, rotating load: {:8.1f} us/step, {:6.1f} us/iteration, {:5.2f} iterations/step\n",
             r.us_per_step, r.us_per_iteration, r.iterations_per_step);
  out["us_per_step_258_rotating_load"] = r.us_per_step;
  out["us_per_iteration_258_rotating_load"] = r.us_per_iteration;
  out["iterations_per_step_258_rotating_load"] = r.iterations_per_step;
  out["provenance"] = hs::common::provenance();
  if (options.json_file) hs::common::write_json(*options.json_file, out);
  return 0;
}

}  // namespace hs::resolved
