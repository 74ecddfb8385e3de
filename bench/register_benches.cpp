// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"
#include "bench/cfddem_bench.hpp"
#include "bench/dem_bench.hpp"
#include "bench/feynman_bench.hpp"
#include "bench/lbm_bench.hpp"
#include "bench/npfem_bench.hpp"
#include "bench/fvm_bench.hpp"
#include "bench/regression_bench.hpp"
#include "bench/resolved_bench.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  r["lbm"] = {"lattice Boltzmann MLUPS vs the memory-bandwidth roofline (128^3 box, 50 um tube)", hs::bench::run_lbm_bench};
  r["npfem"] = {"npFEM membrane step at 258 and 642 vertices (us/step, us/iteration, factorisation)", hs::resolved::bench_npfem};
  r["dem"] = {"DEM ns per particle-step, 1e5 Hertz spheres (in.rbcpack), vs LIGGGHTS", hs::bench::run_dem_bench};
  r["fvm"] = {"PISO fluid on the 3D lid-driven cube vs OpenFOAM icoFoam (ns per cell-step)", hs::bench::run_fvm_bench};
  r["regression"] = {"symbolic regression: 10 Feynman equations, gplearn vs full engine; evaluator speed", hs::bench::run_regression_bench};
  r["feynman"] = {"symbolic regression: 100 AI-Feynman equations x noise 0/0.001/0.01 x 3 seeds as `hemoscale fit` runs, vs gplearn (hours; resumable with --json)", hs::bench::run_feynman_bench};
  r["cfddem"] = {"coupled CFD-DEM tube: s per CFD step and peak RSS for 1e4, 1e5, 1e6 RBCs (periodic), 1e4, 1e5 (open)", hs::bench::run_cfddem_bench};
  r["resolved"] = {"coupled RBC in the campaign tube: s per simulated ms, LBM/IBM/membrane shares, campaign hours", hs::bench::run_resolved_bench};
  return r;
}

}  // namespace hs::app
