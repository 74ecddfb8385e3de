// SPDX-License-Identifier: MIT
// The sampled time series of a stenosis run (centroid, D_x, D_y, D_z, DI, wall gap, flow rate) and its reduction:
// D values upstream, at the throat and downstream, the D_x peak and where it lies, and the dimensionless groups.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/vec3.hpp"
#include "resolved/cases/stenosis_cell_config.hpp"

namespace hs::resolved {

struct StenosisSample {
  double time_s = 0.0;
  common::Vec3 centroid_m;          // unwrapped
  common::Vec3 d;                   // D_i = L_i / D0: projected extents of the membrane along x, y, z over 7.82 um
  double di = 0.0;                  // (L - B) / (L + B) from the principal axes
  double front_x_m = 0.0;           // largest vertex x (where the cell's leading edge is)
  double min_wall_gap_m = 0.0;      // smallest signed distance of a vertex inside the fluid (< 0: in the wall)
  double wall_force_N = 0.0;        // total membrane-wall repulsion at the last membrane step (sum of |F_v|)
  int wall_contacts = 0;            // vertices it pushed
  double ibm_force_x_N = 0.0;       // IBM force spread on the fluid along x, mean over the sample interval
  double traction_x_N = 0.0;        // fluid traction on the membrane along x, mean over the sample interval
  double flow_rate_m2_s = 0.0;      // measured flow rate per width of the box
  double velocity_x_m_s = 0.0;      // mean vertex velocity along x
};

class StenosisSeries {
 public:
  explicit StenosisSeries(const StenosisCellConfig& config) : config_(config) {}
  void add(const StenosisSample& s) { samples_.push_back(s); }
  [[nodiscard]] static std::vector<std::string> columns();
  [[nodiscard]] std::vector<double> row(const StenosisSample& s) const;
  [[nodiscard]] const std::vector<StenosisSample>& samples() const { return samples_; }
  /// Whether the centroid has passed stop_x_m.
  [[nodiscard]] bool passed() const { return !samples_.empty() && samples_.back().centroid_m.x >= config_.stop_x_m; }
  /// summary.json "results": D stations, D_x peak, wall gap, flow and every dimensionless group.
  [[nodiscard]] nlohmann::json results() const;
  [[nodiscard]] std::vector<double> pack() const;
  void unpack(std::span<const double> flat);

 private:
  [[nodiscard]] nlohmann::json groups(double flow_rate_m2_s) const;

  StenosisCellConfig config_;
  std::vector<StenosisSample> samples_;
};

}  // namespace hs::resolved
