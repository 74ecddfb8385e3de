// SPDX-License-Identifier: MIT
// The single list of benchmarks `hemoscale bench NAME` runs: one line per benchmark.
#include "app/registry.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> benchmarks() {
  std::map<std::string, TaskEntry> r;
  return r;
}

}  // namespace hs::app
