// SPDX-License-Identifier: MIT
// The single list of validations `hemoscale validate NAME` runs: one line per validation.
#include "app/registry.hpp"

namespace hs::app {

std::map<std::string, TaskEntry> validations() {
  std::map<std::string, TaskEntry> r;
  return r;
}

}  // namespace hs::app
