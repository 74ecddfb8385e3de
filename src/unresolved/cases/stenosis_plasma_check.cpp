// SPDX-License-Identifier: MIT
// The plasma-only run of a stenosis case.
#include "unresolved/cases/stenosis_plasma_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/errors.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {
namespace {

/// Fluid-volume-weighted mean pressure of the cell layer i.
double layer_pressure_Pa(const FvmSolver& fluid, int i) {
  const FvmGrid& g = fluid.grid();
  double p = 0.0;
  double w = 0.0;
  for (int k = 0; k < g.cells()[2]; ++k) {
    for (int j = 0; j < g.cells()[1]; ++j) {
      const double f = g.fluid_fractions()(i, j, k);
      if (f <= 0.0) continue;
      p += f * fluid.cell_pressure_Pa(i, j, k);
      w += f;
    }
  }
  return w > 0.0 ? p / w : 0.0;
}

/// Section-mean pressure at x, linear between the layers' centres.
double section_pressure_Pa(const FvmSolver& fluid, double x_m) {
  const FvmGrid& g = fluid.grid();
  const double s = (x_m - g.origin_m().x) / g.dx_m() - 0.5;
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, g.cells()[0] - 2);
  const double t = s - i;
  return (1.0 - t) * layer_pressure_Pa(fluid, i) + t * layer_pressure_Pa(fluid, i + 1);
}

}  // namespace

nlohmann::json StenosisPlasmaResult::to_json() const {
  return {{"dx_m", dx_m}, {"pressure_drop_Pa", pressure_drop_Pa}, {"x_a_m", x_a_m}, {"x_b_m", x_b_m},
          {"lubrication_drop_Pa", lubrication_drop_Pa}, {"throat_centreline_m_s", throat_centreline_m_s},
          {"throat_mean_m_s", throat_mean_m_s}, {"centreline_over_mean", throat_centreline_m_s / throat_mean_m_s},
          {"steps", steps}, {"flow_rate_m3_s", flow_rate_m3_s}};
}

StenosisPlasmaResult run_stenosis_plasma(const OpenGeometryConfig& c, double dx_m, long max_steps) {
  if (!c.stenosis_study) throw hs::common::ConfigError("stenosis plasma check: the case has no stenosis [study]");
  const StenosisStudySpec& s = *c.stenosis_study;
  FvmGridSpec spec{.box_m = c.box, .dx_m = dx_m, .sides = {}};
  spec.openings = c.openings;
  const FvmGrid grid(*c.shape, spec);
  FvmSolver fluid(grid, c.fluid, {.dt_s = c.dt_s, .correctors = c.piso_correctors, .coupling = c.pressure_coupling}, {});
  StenosisPlasmaResult r;
  r.dx_m = dx_m;
  r.flow_rate_m3_s = c.inflow_m3_s();
  const double start = s.tube.start_m.x + s.tube.constriction_centre_m - 0.5 * s.tube.constriction_length_m;
  const double end = s.tube.start_m.x + s.tube.constriction_centre_m + 0.5 * s.tube.constriction_length_m;
  r.x_a_m = s.x_lo_m + (start - s.x_lo_m) / 3.0;
  r.x_b_m = s.x_hi_m - (s.x_hi_m - end) / 3.0;
  const auto drop = [&] { return section_pressure_Pa(fluid, r.x_a_m) - section_pressure_Pa(fluid, r.x_b_m); };
  std::vector<double> history;
  for (long n = 0; n < max_steps; ++n) {
    fluid.step();
    history.push_back(drop());
    r.steps = n + 1;
    if (history.size() > 10 && std::abs(history.back() - history[history.size() - 11]) < 1e-7 * std::abs(history.back())) break;
  }
  r.pressure_drop_Pa = history.back();
  r.throat_centreline_m_s = fluid.velocity_at({s.throat_x_m(), s.tube.start_m.y, s.tube.start_m.z}).x;
  r.throat_mean_m_s = r.flow_rate_m3_s / (std::numbers::pi * s.tube.throat_radius_m * s.tube.throat_radius_m);
  // Lubrication: Poiseuille's local gradient 8 mu Q / (pi r^4), Simpson over [x_a, x_b] with 2000 panels.
  const double mu = c.fluid.density_kg_m3 * c.fluid.kinematic_viscosity_m2_s;
  constexpr int kPanels = 2000;
  const double h = (r.x_b_m - r.x_a_m) / kPanels;
  double sum = 0.0;
  for (int k = 0; k <= kPanels; ++k) {
    const double rad = s.radius_at(r.x_a_m + k * h);
    const double w = (k == 0 || k == kPanels) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += w * 8.0 * mu * r.flow_rate_m3_s / (std::numbers::pi * std::pow(rad, 4));
  }
  r.lubrication_drop_Pa = sum * h / 3.0;
  return r;
}

}  // namespace hs::unresolved
