// SPDX-License-Identifier: MIT
// The shear-suspension time series and its reduction to eta_r with a standard error.
#include "resolved/cases/shear_suspension_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/batch_means.hpp"
#include "common/dimensionless_groups.hpp"
#include "resolved/cases/plate_cell_config.hpp"

namespace hs::resolved {
namespace {

/// Share of the run treated as start-up before eta_r is averaged (as the shear case's means).
constexpr double kTransientFraction = 0.5;
/// Batches of the batch-means error (common/batch_means): 10, fewer when the window holds fewer samples.
constexpr int kBatches = 10;

/// eta_r over the settled window by batch means; a window of one sample has no error estimate (SE 0, 0 batches).
common::MeanWithError settled_mean(const std::vector<double>& eta) {
  if (eta.size() < 2) return {.mean = eta.empty() ? 0.0 : eta.front(), .standard_error = 0.0, .batches = 0};
  return common::batch_means(eta, std::min(kBatches, static_cast<int>(eta.size())));
}

}  // namespace

std::vector<std::string> ShearSuspensionSeries::columns() {
  return {"time_s", "stresslet_xy_sum_N_m", "relative_viscosity", "di_mean", "min_cell_distance_m", "contact_pairs",
          "min_wall_distance_m", "cell_volume_sum_m3"};
}

double ShearSuspensionSeries::relative_viscosity(const SuspensionSample& s) const {
  const double mu = config_.density_kg_m3 * config_.kinematic_viscosity_m2_s;
  const double box_m3 = config_.gap_m * config_.length_m * config_.width_m;
  return 1.0 + s.stresslet_xy_N_m / (box_m3 * mu * config_.shear_rate_1_s);
}

std::vector<double> ShearSuspensionSeries::row(std::size_t i) const {
  const SuspensionSample& s = samples_.at(i);
  return {s.time_s, s.stresslet_xy_N_m, relative_viscosity(s), s.di_mean, s.min_cell_distance_m,
          static_cast<double>(s.contact_pairs), s.min_wall_distance_m, s.volume_m3};
}

nlohmann::json ShearSuspensionSeries::results() const {
  nlohmann::json r;
  const double mu = config_.density_kg_m3 * config_.kinematic_viscosity_m2_s;
  const double box_m3 = config_.gap_m * config_.length_m * config_.width_m;
  r["cells"] = cells_;
  r["hematocrit"] = static_cast<double>(cells_) * cell_volume_m3_ / box_m3;   // reached (N whole cells)
  r["hematocrit_asked"] = config_.hematocrit;
  r["shear_rate_1_s"] = config_.shear_rate_1_s;
  r["ca"] = common::capillary_number(mu, config_.shear_rate_1_s, kCellRadius_m, config_.membrane.material.shear_modulus_N_m);
  r["reynolds"] = config_.reynolds;                                                    // rho gamma H^2 / mu
  r["particle_reynolds"] = config_.shear_rate_1_s * kCellRadius_m * kCellRadius_m / config_.kinematic_viscosity_m2_s;
  r["confinement"] = 2.0 * kCellRadius_m / config_.gap_m;
  r["samples"] = samples_.size();
  if (samples_.empty()) return r;
  const auto from = static_cast<std::size_t>(std::floor(kTransientFraction * static_cast<double>(samples_.size())));
  std::vector<double> eta;
  double volume = 0.0, di = 0.0;
  for (std::size_t i = from; i < samples_.size(); ++i) {
    eta.push_back(relative_viscosity(samples_[i]));
    volume += samples_[i].volume_m3;
    di += samples_[i].di_mean;
  }
  const common::MeanWithError m = settled_mean(eta);
  r["relative_viscosity"] = m.mean;
  r["relative_viscosity_standard_error"] = m.standard_error;
  r["relative_viscosity_batches"] = m.batches;
  // The batches drop the window's remainder (< 10 samples) at its front, the less settled end: the mean's window.
  const auto batches = static_cast<std::size_t>(std::max(m.batches, 1));
  const std::size_t used = eta.size() / batches * batches;
  r["settled_window_s"] = {samples_[samples_.size() - used].time_s, samples_.back().time_s};
  const double n = static_cast<double>(eta.size());
  // Per cell, the dilute-limit reading: [eta] = (eta_r - 1) / phi with the cells' mean volume (Batchelor 1970).
  const double phi = volume / n / box_m3;
  r["hematocrit_measured_volume"] = phi;
  r["intrinsic_viscosity"] = phi > 0.0 ? (m.mean - 1.0) / phi : 0.0;
  r["intrinsic_viscosity_standard_error"] = phi > 0.0 ? m.standard_error / phi : 0.0;
  r["di_mean"] = di / n;
  double min_cell = std::numeric_limits<double>::infinity(), min_wall = std::numeric_limits<double>::infinity();
  int max_pairs = 0;
  for (const auto& s : samples_) {
    min_cell = std::min(min_cell, s.min_cell_distance_m);
    min_wall = std::min(min_wall, s.min_wall_distance_m);
    max_pairs = std::max(max_pairs, s.contact_pairs);
  }
  r["min_cell_distance_m"] = std::isfinite(min_cell) ? min_cell : 0.0;
  r["min_wall_distance_m"] = std::isfinite(min_wall) ? min_wall : 0.0;
  r["max_contact_pairs"] = max_pairs;
  r["mean_stresslet_xy_sum_N_m"] = (m.mean - 1.0) * box_m3 * mu * config_.shear_rate_1_s;
  return r;
}

}  // namespace hs::resolved
