// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"
#include "bench/fvm_bench.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  r["fvm"] = {"PISO fluid on the 3D lid-driven cube vs OpenFOAM icoFoam (ns per cell-step)", hs::bench::run_fvm_bench};
  return r;
}

}  // namespace hs::app
