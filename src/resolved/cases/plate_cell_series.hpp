// SPDX-License-Identifier: MIT
// The sampled time series of a shear or migration run and its reduction: flow mode, tumbling period vs Jeffery,
// tank-treading frequency, inclination (shear); lateral position and migration speed (migration).
#pragma once

#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/vec3.hpp"
#include "resolved/cases/plate_cell_config.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/membrane/membrane_energy_balance.hpp"

namespace hs::resolved {

struct PlateCellSample {
  double time_s = 0.0;
  double di = 0.0;
  double di_gyration = 0.0;        // CellShape::gyration_deformation_index (all vertices count)
  double inclination_rad = 0.0;    // long axis in the shear plane (x, y) against the flow (x), in (-pi/2, pi/2]
  double marker_phase_rad = 0.0;   // marker vertex about the centroid in the shear plane, atan2(dy, dx)
  common::Vec3 centroid_m;         // unwrapped
  common::Vec3 velocity_m_s;       // mean vertex velocity
  MembraneEnergySnapshot energy;   // the membrane's energy books and stored energies (power balance)
  double stresslet_xy_N_m = 0.0;   // S_xy of the fluid's forces on the membrane (measure/stresslet.hpp)
  double volume_m3 = 0.0;          // the cell's enclosed volume
  double taylor_deformation = 0.0; // D of the equivalent ellipsoid in the shear plane (the capsule literature's)
};

class PlateCellSeries {
 public:
  explicit PlateCellSeries(const PlateCellConfig& config) : config_(config) {}
  void add(const PlateCellSample& s) { samples_.push_back(s); }
  [[nodiscard]] static std::vector<std::string> columns();
  /// The row of sample i; its powers are the means since sample i - 1 (since the start for the first).
  [[nodiscard]] std::vector<double> row(std::size_t i) const;
  [[nodiscard]] const std::vector<PlateCellSample>& samples() const { return samples_; }
  /// summary.json "results": the reduction of the case's flow and all dimensionless groups.
  [[nodiscard]] nlohmann::json results() const;
  /// summary.json "membrane_energy": the power balance over the whole run and over the settled second half.
  [[nodiscard]] nlohmann::json energy_results() const;
  /// Shear: whether the membrane tank-treads (or swings) over the second half and its whole revolutions there are
  /// settled (the last two as long as the two before); after at least kMinJefferyPeriodsToStop Jeffery periods.
  [[nodiscard]] bool tank_treading_settled() const;
  [[nodiscard]] std::vector<double> pack() const;
  void unpack(std::span<const double> flat);

 private:
  [[nodiscard]] nlohmann::json shear_results() const;
  [[nodiscard]] nlohmann::json migration_results() const;
  [[nodiscard]] nlohmann::json groups() const;
  void settled_tank_treading(FlowMode mode, std::span<const double> t, std::span<const double> phase,
                             std::span<const double> di, std::size_t from, nlohmann::json& r) const;

  PlateCellConfig config_;
  std::vector<PlateCellSample> samples_;
};

/// Tumbling period from the unwrapped long-axis angle: the times at which the axis passes the flow direction
/// (angle = k pi) are half turns; period = 2 (t_last - t_first) / (crossings - 1). 0 with fewer than 2 crossings.
struct TumblingPeriod {
  double period_s = 0.0;
  int half_turns = 0;
};
TumblingPeriod tumbling_period(std::span<const double> time_s, std::span<const double> inclination_rad);

}  // namespace hs::resolved
