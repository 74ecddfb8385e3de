// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"
#include "bench/regression_bench.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  r["regression"] = {"symbolic regression: 10 Feynman equations, gplearn vs full engine; evaluator speed", hs::bench::run_regression_bench};
  return r;
}

}  // namespace hs::app
