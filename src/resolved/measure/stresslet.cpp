// SPDX-License-Identifier: MIT
// The stresslet sum over membrane vertices.
#include "resolved/measure/stresslet.hpp"

#include <stdexcept>

namespace hs::resolved {

Stresslet stresslet(std::span<const common::Vec3> vertices_m, std::span<const common::Vec3> fluid_force_N) {
  if (vertices_m.size() != fluid_force_N.size() || vertices_m.empty()) {
    throw std::invalid_argument("stresslet: one force per vertex is needed");
  }
  common::Vec3 centroid;
  for (const auto& x : vertices_m) centroid += x;
  centroid = centroid / static_cast<double>(vertices_m.size());
  Stresslet s{};
  for (std::size_t k = 0; k < vertices_m.size(); ++k) {
    const common::Vec3 r = vertices_m[k] - centroid;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) s[i][j] += 0.5 * (r[i] * fluid_force_N[k][j] + r[j] * fluid_force_N[k][i]);
    }
  }
  const double third_trace = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  for (int i = 0; i < 3; ++i) s[i][i] -= third_trace;
  return s;
}

double intrinsic_viscosity(const Stresslet& s, double viscosity_Pa_s, double shear_rate_per_s, double cell_volume_m3,
                           int flow_axis, int gradient_axis) {
  return s[flow_axis][gradient_axis] / (viscosity_Pa_s * shear_rate_per_s * cell_volume_m3);
}

}  // namespace hs::resolved
