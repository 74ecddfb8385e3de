// SPDX-License-Identifier: MIT
// The sampled time series of a tube-cell run and its reduction to period averages and dimensionless groups.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/vec3.hpp"
#include "resolved/cases/tube_cell_config.hpp"

namespace hs::resolved {

/// One sample: forces averaged over the sampling interval, shape at its end.
struct TubeCellSample {
  double time_s = 0.0;
  common::Vec3 force_N;            // hydrodynamic force on the cell: minus the IBM force on the fluid
  common::Vec3 traction_force_N;   // sum of the stress-based membrane forces (what deforms the membrane)
  common::Vec3 centroid_m;
  double axial_velocity_m_s = 0.0; // centre-of-mass velocity along the tube axis
  double di = 0.0;
  double inclination_rad = 0.0;
  double marker_phase_rad = 0.0;
  /// Disc normal against the local vorticity e_theta (normal_to_vorticity_angle): ~0 rolling, ~pi/2 turning in the
  /// shear plane. NaN for samples restored from a checkpoint written before the measure existed.
  double normal_to_vorticity_rad = std::numeric_limits<double>::quiet_NaN();
};

/// Columns of timeseries.csv, and the values of one row.
std::vector<std::string> tube_cell_columns();

class TubeCellSeries {
 public:
  TubeCellSeries(const TubeCellConfig& config, double cell_volume_m3);
  void add(const TubeCellSample& sample);
  [[nodiscard]] std::vector<double> row(const TubeCellSample& sample) const;
  /// Whether Cd (drag set-up), or DI and Cl (lift set-up), have settled over settle_periods whole periods
  /// (measure/periodic_signal), or are steady over steady_window_s() (Cl within lift_settle_spread).
  [[nodiscard]] bool settled() const;
  /// Period averages, flow mode and dimensionless groups for summary.json "results".
  [[nodiscard]] nlohmann::json results() const;
  [[nodiscard]] std::size_t size() const { return samples_.size(); }
  [[nodiscard]] const std::vector<TubeCellSample>& samples() const { return samples_; }
  /// Flat copy of the samples for checkpoints, and its inverse (replaces the series).
  [[nodiscard]] std::vector<double> pack() const;
  void unpack(std::span<const double> flat);
  /// Trailing window over which a non-periodic (steady) run must be constant: max(5 R^2/nu, one Jeffery period).
  [[nodiscard]] double steady_window_s() const;

 private:
  [[nodiscard]] double radial_m(const TubeCellSample& s) const;
  [[nodiscard]] double undisturbed_speed_m_s(const TubeCellSample& s) const;   // u(r) at the centre of mass
  [[nodiscard]] double relative_speed_m_s(const TubeCellSample& s) const;      // u(r) - u_p
  [[nodiscard]] double drag_N(const TubeCellSample& s) const { return s.force_N.z; }
  [[nodiscard]] double lift_N(const TubeCellSample& s) const;
  [[nodiscard]] std::vector<double> column(int which) const;
  /// Samples before the end of the start-up transient (first quarter, and kMembraneTransientTimes relaxation times).
  [[nodiscard]] std::size_t transient_samples() const;
  /// Whether one signal has settled: `settle_periods` periods agree, or it is steady (whole range, or for a noisy
  /// signal the means of three thirds of the window) within `spread` of max(|mean|, floor).
  [[nodiscard]] bool signal_settled(const std::vector<double>& signal, double spread, double floor, bool noisy) const;

  TubeCellConfig config_;
  double particle_diameter_m_;
  std::vector<TubeCellSample> samples_;
};

}  // namespace hs::resolved
