// SPDX-License-Identifier: MIT
// How often a run's closures saw inputs outside their validity box: one JSON block for every study measurement.
#pragma once

#include <nlohmann/json.hpp>

#include "unresolved/coupling/cfd_dem_coupling.hpp"

namespace hs::unresolved {

/// {"drag"|"lift"|"deformation": {evaluations, outside_validity, outside_share, report}} for each closure present
/// (this run's evaluations; a resumed run: since the resume).
[[nodiscard]] inline nlohmann::json closure_validity_report(const CouplingClosures& cl) {
  nlohmann::json validity = nlohmann::json::object();
  const auto usage = [&validity](const char* what, const hs::closures::Closure* c) {
    if (c == nullptr) return;
    const long n = c->evaluations();
    validity[what] = {{"evaluations", n}, {"outside_validity", c->outside_validity()},
                      {"outside_share", n > 0 ? static_cast<double>(c->outside_validity()) / static_cast<double>(n) : 0.0},
                      {"report", c->usage_report()}};
  };
  usage("drag", cl.drag.get());
  usage("lift", cl.lift.get());
  usage("deformation", cl.deformation.get());
  return validity;
}

}  // namespace hs::unresolved
