// SPDX-License-Identifier: MIT
// The shear-suspension time series and its reduction to eta_r with a standard error.
#include "resolved/cases/shear_suspension_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/dimensionless_groups.hpp"
#include "resolved/cases/plate_cell_config.hpp"

namespace hs::resolved {
namespace {

/// Share of the run treated as start-up before eta_r is averaged (as the shear case's means).
constexpr double kTransientFraction = 0.5;
/// Batches of the batch-means error: 10 when there are samples enough (>= 2 a batch), fewer otherwise.
constexpr int kBatches = 10;

}  // namespace

BatchMean batch_mean(std::span<const double> x, int batches) {
  BatchMean out;
  if (x.empty()) return out;
  double sum = 0.0;
  for (const double v : x) sum += v;
  out.mean = sum / static_cast<double>(x.size());
  const std::size_t b = std::min<std::size_t>(static_cast<std::size_t>(std::max(batches, 0)), x.size());
  if (b < 2) return out;
  const std::size_t per = x.size() / b;   // the last x.size() % b samples enter the mean only
  std::vector<double> means(b, 0.0);
  for (std::size_t i = 0; i < b; ++i) {
    for (std::size_t k = 0; k < per; ++k) means[i] += x[i * per + k];
    means[i] /= static_cast<double>(per);
  }
  double m = 0.0;
  for (const double v : means) m += v;
  m /= static_cast<double>(b);
  double var = 0.0;
  for (const double v : means) var += (v - m) * (v - m);
  var /= static_cast<double>(b - 1);
  out.standard_error = std::sqrt(var / static_cast<double>(b));
  out.batches = static_cast<int>(b);
  return out;
}

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
  const BatchMean m = batch_mean(eta, kBatches);
  r["relative_viscosity"] = m.mean;
  r["relative_viscosity_standard_error"] = m.standard_error;
  r["relative_viscosity_batches"] = m.batches;
  r["settled_window_s"] = {samples_[from].time_s, samples_.back().time_s};
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
