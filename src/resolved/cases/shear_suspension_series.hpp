// SPDX-License-Identifier: MIT
// The sampled time series of a shear-suspension run and its reduction: the suspension's relative viscosity from the
// cells' summed stresslets, with its standard error, and the cells' closest approach.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "resolved/cases/shear_suspension_config.hpp"

namespace hs::resolved {

struct SuspensionSample {
  double time_s = 0.0;
  double stresslet_xy_N_m = 0.0;     // sum over the cells of S_xy (measure/stresslet.hpp)
  double di_mean = 0.0;              // mean deformation index of the cells
  double min_cell_distance_m = 0.0;  // closest vertices of different cells (minimum image), within the search range
  int contact_pairs = 0;             // vertex pairs inside the contact range at the last membrane step
  double min_wall_distance_m = 0.0;  // closest vertex to a plate
  double volume_m3 = 0.0;            // sum of the cells' enclosed volumes
};

class ShearSuspensionSeries {
 public:
  ShearSuspensionSeries(const ShearSuspensionConfig& config, int cells, double cell_volume_m3)
      : config_(config), cells_(cells), cell_volume_m3_(cell_volume_m3) {}
  void add(const SuspensionSample& s) { samples_.push_back(s); }
  [[nodiscard]] static std::vector<std::string> columns();
  [[nodiscard]] std::vector<double> row(std::size_t i) const;
  [[nodiscard]] const std::vector<SuspensionSample>& samples() const { return samples_; }
  /// eta_r = 1 + <sum S_xy> / (V_box mu gamma_dot) over the settled window (the second half of the samples), its
  /// standard error, hematocrit, Ca, Re; the closest approach of two cells and of a cell to a plate over the run.
  [[nodiscard]] nlohmann::json results() const;
  /// The suspension's relative viscosity of sample i alone.
  [[nodiscard]] double relative_viscosity(const SuspensionSample& s) const;

 private:
  ShearSuspensionConfig config_;
  int cells_ = 0;
  double cell_volume_m3_ = 0.0;
  std::vector<SuspensionSample> samples_;
};

}  // namespace hs::resolved
