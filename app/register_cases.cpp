// SPDX-License-Identifier: MIT
// The single list of case types `hemoscale run` knows: one line per case.
#include "app/registry.hpp"
#include "unresolved/cases/tube_plasma.hpp"

namespace hs::app {

std::map<std::string, Entry> case_types() {
  std::map<std::string, Entry> r;
  // r["tube-poiseuille"] = {"plasma in a periodic tube, checked against Poiseuille", hs::resolved::run_tube_poiseuille};
  r["tube-plasma"] = {"plasma alone in a periodic tube (unresolved FVM), checked against Poiseuille", hs::unresolved::run_tube_plasma};
  return r;
}

}  // namespace hs::app
