// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"
#include "bench/lbm_bench.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  r["lbm"] = {"lattice Boltzmann MLUPS vs the memory-bandwidth roofline (128^3 box, 50 um tube)", hs::bench::run_lbm_bench};
  return r;
}

}  // namespace hs::app
