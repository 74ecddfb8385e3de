// SPDX-License-Identifier: MIT
// Classifies the motion of a cell in shear.
#include "resolved/measure/flow_mode.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace hs::resolved {

std::string to_string(FlowMode mode) {
  switch (mode) {
    case FlowMode::steady: return "steady";
    case FlowMode::tank_treading: return "tank-treading";
    case FlowMode::tumbling: return "tumbling";
    case FlowMode::intermediate: return "intermediate";
  }
  return "unknown";
}

double jeffery_period(double shear_rate_1_s, double aspect_ratio) {
  return 2.0 * std::numbers::pi * (aspect_ratio + 1.0 / aspect_ratio) / shear_rate_1_s;
}

void unwrap(std::span<double> angles, double modulus) {
  double offset = 0.0;
  for (std::size_t i = 1; i < angles.size(); ++i) {
    const double raw = angles[i] + offset;
    const double jump = raw - angles[i - 1];
    if (jump > 0.5 * modulus) offset -= modulus * std::round(jump / modulus);
    if (jump < -0.5 * modulus) offset -= modulus * std::round(jump / modulus);
    angles[i] += offset;
  }
}

FlowMode classify_flow_mode(std::span<const double> inclination_rad, std::span<const double> marker_phase_rad,
                            double swing_limit_rad) {
  if (inclination_rad.size() < 2) return FlowMode::steady;
  std::vector<double> incl(inclination_rad.begin(), inclination_rad.end());
  std::vector<double> phase(marker_phase_rad.begin(), marker_phase_rad.end());
  unwrap(incl, std::numbers::pi);          // an axis repeats every pi
  unwrap(phase, 2.0 * std::numbers::pi);
  const auto [ilo, ihi] = std::minmax_element(incl.begin(), incl.end());
  const double turn = std::abs(incl.back() - incl.front());
  const double range = *ihi - *ilo;
  double marker_turn = 0.0;
  if (phase.size() >= 2) marker_turn = std::abs(phase.back() - phase.front());
  if (turn > std::numbers::pi) return FlowMode::tumbling;
  if (range < swing_limit_rad && marker_turn > 2.0 * std::numbers::pi) return FlowMode::tank_treading;
  if (range < swing_limit_rad && marker_turn < 0.5 * std::numbers::pi) return FlowMode::steady;
  return FlowMode::intermediate;
}

std::string classify_disc_orientation(double mean_normal_to_vorticity_rad) {
  if (std::isnan(mean_normal_to_vorticity_rad)) return "";
  const double mean_deg = mean_normal_to_vorticity_rad * 180.0 / std::numbers::pi;
  if (mean_deg < 30.0) return "rolling";
  if (mean_deg > 60.0) return "in-shear-plane";
  return "oblique";
}

}  // namespace hs::resolved
