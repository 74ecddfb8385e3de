// SPDX-License-Identifier: MIT
// The stenosis study's plasma-only check: the FVM alone (no cells) on a stenosis case's tube and openings, run to its
// steady Stokes flow, for the pressure drop across the constriction (against a finer grid) and the throat's
// centreline velocity (against the flow rate over the throat's area).
#pragma once

#include <nlohmann/json.hpp>

#include "unresolved/cases/open_geometry.hpp"

namespace hs::unresolved {

struct StenosisPlasmaResult {
  double dx_m = 0.0;
  double pressure_drop_Pa = 0.0;       // section-mean pressure at x_a minus that at x_b
  double x_a_m = 0.0;                  // stations in the straight tube: 1/3 of the inlet length and of the outlet length
  double x_b_m = 0.0;                  // inside the tube's ends
  double lubrication_drop_Pa = 0.0;    // int 8 mu Q / (pi r(x)^4) dx over [x_a, x_b] (slowly varying tube; a scale)
  double throat_centreline_m_s = 0.0;  // axial fluid velocity on the axis at the throat
  double throat_mean_m_s = 0.0;        // Q / (pi r_t^2)
  long steps = 0;
  double flow_rate_m3_s = 0.0;
  [[nodiscard]] nlohmann::json to_json() const;
};

/// Runs the plasma of `c` (its shape, box, openings, fluid, dt and PISO correctors) on a grid of spacing dx_m until
/// the pressure drop changes by less than 1e-7 of itself over 10 steps (at most max_steps). `c` must carry a stenosis
/// study (the stations come from its tube).
[[nodiscard]] StenosisPlasmaResult run_stenosis_plasma(const OpenGeometryConfig& c, double dx_m, long max_steps = 4000);

}  // namespace hs::unresolved
