// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"
#include "bench/dem_bench.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  r["dem"] = {"DEM ns per particle-step, 1e5 Hertz spheres (in.rbcpack), vs LIGGGHTS", hs::bench::run_dem_bench};
  return r;
}

}  // namespace hs::app
