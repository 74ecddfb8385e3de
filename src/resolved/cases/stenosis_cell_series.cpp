// SPDX-License-Identifier: MIT
// The sampled time series of a stenosis run and its reduction to D stations, the D_x peak and dimensionless groups.
#include "resolved/cases/stenosis_cell_series.hpp"

#include <algorithm>
#include <cmath>

#include "common/dimensionless_groups.hpp"

namespace hs::resolved {
namespace {

constexpr std::size_t kPackedFields = 16;

nlohmann::json station(const StenosisSample& s, double throat_x_m) {
  return {{"time_s", s.time_s}, {"centroid_x_m", s.centroid_m.x}, {"x_minus_throat_m", s.centroid_m.x - throat_x_m},
          {"centroid_y_m", s.centroid_m.y}, {"d_x", s.d.x}, {"d_y", s.d.y}, {"d_z", s.d.z}, {"di", s.di}};
}

}  // namespace

std::vector<std::string> StenosisSeries::columns() {
  return {"time_s", "centroid_x_m", "centroid_y_m", "centroid_z_m", "d_x", "d_y", "d_z", "di", "front_x_m",
          "min_wall_gap_m", "wall_force_N", "wall_contacts", "ibm_force_x_N", "traction_x_N", "flow_rate_m2_s",
          "velocity_x_m_s"};
}

std::vector<double> StenosisSeries::row(const StenosisSample& s) const {
  return {s.time_s, s.centroid_m.x, s.centroid_m.y, s.centroid_m.z, s.d.x, s.d.y, s.d.z, s.di, s.front_x_m,
          s.min_wall_gap_m, s.wall_force_N, static_cast<double>(s.wall_contacts), s.ibm_force_x_N, s.traction_x_N,
          s.flow_rate_m2_s, s.velocity_x_m_s};
}

std::vector<double> StenosisSeries::pack() const {
  std::vector<double> out;
  out.reserve(kPackedFields * samples_.size());
  for (const auto& s : samples_) {
    const auto r = row(s);
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

void StenosisSeries::unpack(std::span<const double> flat) {
  samples_.clear();
  for (std::size_t k = 0; k + kPackedFields <= flat.size(); k += kPackedFields) {
    const double* v = flat.data() + k;
    samples_.push_back({.time_s = v[0], .centroid_m = {v[1], v[2], v[3]}, .d = {v[4], v[5], v[6]}, .di = v[7],
                        .front_x_m = v[8], .min_wall_gap_m = v[9], .wall_force_N = v[10],
                        .wall_contacts = static_cast<int>(v[11]), .ibm_force_x_N = v[12], .traction_x_N = v[13],
                        .flow_rate_m2_s = v[14], .velocity_x_m_s = v[15]});
  }
}

nlohmann::json StenosisSeries::groups(double flow_rate_m2_s) const {
  const StenosisCellConfig& c = config_;
  const double nu = c.kinematic_viscosity_m2_s;
  const double mu = nu * c.density_kg_m3;
  const double k_s = c.membrane.material.shear_modulus_N_m;
  const double a = 0.5 * kCellDiameter_m;
  const double q = flow_rate_m2_s;
  // Plane Poiseuille estimates: mean velocity q / h, wall shear rate 6 q / h^2 (open channel h = H, throat h = h_t).
  const double gamma_open = 6.0 * q / (c.height_m * c.height_m);
  const double gamma_throat = 6.0 * q / (c.throat_height_m * c.throat_height_m);
  nlohmann::json g;
  g["flow_rate_m2_s"] = q;
  g["flow_rate_target_m2_s"] = c.flow_rate_m2_s();
  g["mean_velocity_m_s"] = q / c.height_m;
  g["mean_velocity_throat_m_s"] = q / c.throat_height_m;
  g["reynolds"] = q / nu;   // rho U H / mu with U = q / H (the same as rho U_t h_t / mu at the throat)
  g["wall_shear_rate_open_1_s"] = gamma_open;
  g["wall_shear_rate_throat_1_s"] = gamma_throat;
  g["ca_open"] = common::capillary_number(mu, gamma_open, a, k_s);
  g["ca_throat"] = common::capillary_number(mu, gamma_throat, a, k_s);
  g["particle_reynolds_throat"] = gamma_throat * a * a / nu;
  g["confinement_open"] = kCellDiameter_m / c.height_m;
  g["confinement_throat"] = kCellDiameter_m / c.throat_height_m;
  g["throat_height_m"] = c.throat_height_m;
  g["height_m"] = c.height_m;
  g["constriction_length_m"] = c.constriction_length_m;
  return g;
}

nlohmann::json StenosisSeries::results() const {
  const StenosisCellConfig& c = config_;
  double q_sum = 0.0;
  for (const auto& s : samples_) q_sum += s.flow_rate_m2_s;
  nlohmann::json r = groups(samples_.empty() ? c.flow_rate_m2_s() : q_sum / static_cast<double>(samples_.size()));
  r["samples"] = samples_.size();
  r["passed_stop_x"] = passed();
  if (samples_.empty()) return r;
  const double entry = c.throat_x_m - 0.5 * c.constriction_length_m;
  // Upstream: the last sample whose leading edge is still before the constriction entry (else the first sample).
  std::size_t up = 0;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    if (samples_[i].front_x_m < entry) up = i;
  }
  const auto throat = std::min_element(samples_.begin(), samples_.end(), [&](const auto& a, const auto& b) {
    return std::abs(a.centroid_m.x - c.throat_x_m) < std::abs(b.centroid_m.x - c.throat_x_m);
  });
  const auto peak = std::max_element(samples_.begin(), samples_.end(), [](const auto& a, const auto& b) { return a.d.x < b.d.x; });
  const auto gap = std::min_element(samples_.begin(), samples_.end(),
                                    [](const auto& a, const auto& b) { return a.min_wall_gap_m < b.min_wall_gap_m; });
  r["upstream"] = station(samples_[up], c.throat_x_m);
  r["throat"] = station(*throat, c.throat_x_m);
  r["downstream"] = station(samples_.back(), c.throat_x_m);
  r["d_x_max"] = peak->d.x;
  r["d_x_max_at"] = station(*peak, c.throat_x_m);
  r["d_x_max_over_upstream"] = peak->d.x / samples_[up].d.x;
  r["min_wall_gap_m"] = gap->min_wall_gap_m;
  r["min_wall_gap_at_x_minus_throat_m"] = gap->centroid_m.x - c.throat_x_m;
  const auto push = std::max_element(samples_.begin(), samples_.end(),
                                     [](const auto& a, const auto& b) { return a.wall_force_N < b.wall_force_N; });
  r["wall_force_max_N"] = push->wall_force_N;
  r["wall_force_max_at_x_minus_throat_m"] = push->centroid_m.x - c.throat_x_m;
  r["samples_with_wall_contact"] = std::count_if(samples_.begin(), samples_.end(),
                                                 [](const auto& s) { return s.wall_contacts > 0; });
  r["samples_with_vertex_in_wall"] = std::count_if(samples_.begin(), samples_.end(),
                                                   [](const auto& s) { return s.min_wall_gap_m < 0.0; });
  return r;
}

}  // namespace hs::resolved
