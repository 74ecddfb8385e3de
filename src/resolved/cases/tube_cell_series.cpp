// SPDX-License-Identifier: MIT
// The sampled time series of a tube-cell run and its reduction to period averages and dimensionless groups.
#include "resolved/cases/tube_cell_series.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "common/dimensionless_groups.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/measure/periodic_signal.hpp"

namespace hs::resolved {
namespace {

/// Share of the series discarded as start-up transient before settling is judged.
constexpr double kTransientFraction = 0.25;

enum Column { kDi, kCd, kCl, kInclination, kPhase, kNormalToVorticity };

/// Viscous spin-up times R^2 / nu that a steady window must span at least.
constexpr double kSpinUpTimes = 5.0;

/// max - min over the trailing `count` samples, relative to max(|their mean|, floor).
double trailing_relative_range(const std::vector<double>& v, std::size_t count, double floor) {
  const auto begin = v.end() - static_cast<std::ptrdiff_t>(count);
  const auto [lo, hi] = std::minmax_element(begin, v.end());
  double mean = 0.0;
  for (auto it = begin; it != v.end(); ++it) mean += *it;
  mean /= static_cast<double>(count);
  return (*hi - *lo) / std::max({std::abs(mean), floor, 1e-300});
}

/// Spread of the means of the trailing window's three thirds, relative to max(|the window's mean|, floor): the
/// steady test for a noisy signal (the lift), whose sample-to-sample range never falls to a few per cent.
double trailing_thirds_spread(const std::vector<double>& v, std::size_t count, double floor) {
  const std::size_t third = count / 3;
  const auto begin = v.end() - static_cast<std::ptrdiff_t>(3 * third);
  std::array<double, 3> means{};
  for (std::size_t k = 0; k < 3 * third; ++k) means[k / third] += begin[static_cast<std::ptrdiff_t>(k)] / static_cast<double>(third);
  const auto [lo, hi] = std::minmax_element(means.begin(), means.end());
  const double mean = (means[0] + means[1] + means[2]) / 3.0;
  return (*hi - *lo) / std::max({std::abs(mean), floor, 1e-300});
}

/// Mean of the finite values (NaN when there are none).
double finite_mean(const std::vector<double>& v) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const double x : v) {
    if (std::isfinite(x)) {
      sum += x;
      ++n;
    }
  }
  return n > 0 ? sum / static_cast<double>(n) : std::nan("");
}

nlohmann::json average_json(const PeriodAverage& a) {
  return {{"mean", a.mean}, {"spread", a.spread}, {"periods", a.periods}, {"period_s", a.period_s}, {"steady", a.steady}};
}

}  // namespace

std::vector<std::string> tube_cell_columns() {
  return {"time_s", "drag_N", "lift_N", "cd", "cl", "di", "inclination_rad", "centroid_x_m", "centroid_y_m",
          "centroid_z_m", "r_star", "axial_velocity_m_s", "traction_drag_N", "traction_lift_N", "normal_to_vorticity_rad"};
}

TubeCellSeries::TubeCellSeries(const TubeCellConfig& config, double cell_volume_m3)
    : config_(config), particle_diameter_m_(std::cbrt(6.0 * cell_volume_m3 / std::numbers::pi)) {}

void TubeCellSeries::add(const TubeCellSample& sample) { samples_.push_back(sample); }

namespace {
constexpr std::size_t kPackedFields = 15;
/// The last slot was a spare 0 before the disc orientation was sampled. The angle (in [0, pi/2], exactly 0 for the
/// resting disc's rolling start) is stored plus this offset, so that a 0 still means "not sampled" (older checkpoints).
constexpr double kOrientationOffset = 1.0;
}  // namespace

std::vector<double> TubeCellSeries::pack() const {
  std::vector<double> out;
  out.reserve(kPackedFields * samples_.size());
  for (const auto& s : samples_) {
    out.insert(out.end(), {s.time_s, s.force_N.x, s.force_N.y, s.force_N.z, s.traction_force_N.x, s.traction_force_N.y,
                           s.traction_force_N.z, s.centroid_m.x, s.centroid_m.y, s.centroid_m.z, s.axial_velocity_m_s,
                           s.di, s.inclination_rad, s.marker_phase_rad, kOrientationOffset + s.normal_to_vorticity_rad});
  }
  return out;
}

void TubeCellSeries::unpack(std::span<const double> flat) {
  samples_.clear();
  for (std::size_t k = 0; k + kPackedFields <= flat.size(); k += kPackedFields) {
    const double* v = flat.data() + k;
    samples_.push_back({.time_s = v[0], .force_N = {v[1], v[2], v[3]}, .traction_force_N = {v[4], v[5], v[6]},
                        .centroid_m = {v[7], v[8], v[9]}, .axial_velocity_m_s = v[10], .di = v[11],
                        .inclination_rad = v[12], .marker_phase_rad = v[13],
                        .normal_to_vorticity_rad = v[14] == 0.0 ? std::numeric_limits<double>::quiet_NaN()
                                                                : v[14] - kOrientationOffset});
  }
}

double TubeCellSeries::radial_m(const TubeCellSample& s) const { return std::hypot(s.centroid_m.x, s.centroid_m.y); }

double TubeCellSeries::lift_N(const TubeCellSample& s) const {
  const double r = radial_m(s);
  if (r < 1e-12) return s.force_N.x;   // on the axis: the x direction (the direction the cell was displaced in)
  return (s.force_N.x * s.centroid_m.x + s.force_N.y * s.centroid_m.y) / r;
}

double TubeCellSeries::undisturbed_speed_m_s(const TubeCellSample& s) const {
  return common::poiseuille_velocity(config_.u_max_m_s, radial_m(s), config_.radius_m);
}

double TubeCellSeries::relative_speed_m_s(const TubeCellSample& s) const {
  return undisturbed_speed_m_s(s) - s.axial_velocity_m_s;
}

std::vector<double> TubeCellSeries::row(const TubeCellSample& s) const {
  const double u = relative_speed_m_s(s);
  // Cl is normalised by the undisturbed flow speed u(r), not by the free cell's small slip (docs/coefficients.md
  // "Why Cl uses u(r)"): lift / slip^2 had a period-to-period spread larger than its mean.
  const double u_flow = undisturbed_speed_m_s(s);
  const double rho = config_.density_kg_m3;
  const double r = radial_m(s);
  const double traction_lift = r < 1e-12 ? s.traction_force_N.x
                                         : (s.traction_force_N.x * s.centroid_m.x + s.traction_force_N.y * s.centroid_m.y) / r;
  return {s.time_s, drag_N(s), lift_N(s), common::force_coefficient(drag_N(s), rho, u, particle_diameter_m_),
          common::force_coefficient(lift_N(s), rho, u_flow, particle_diameter_m_), s.di, s.inclination_rad,
          s.centroid_m.x, s.centroid_m.y, s.centroid_m.z, r / config_.radius_m, s.axial_velocity_m_s,
          s.traction_force_N.z, traction_lift, s.normal_to_vorticity_rad};
}

std::vector<double> TubeCellSeries::column(int which) const {
  std::vector<double> out;
  out.reserve(samples_.size());
  for (const auto& s : samples_) {
    const auto r = row(s);
    switch (which) {
      case kDi: out.push_back(s.di); break;
      case kCd: out.push_back(r[3]); break;
      case kCl: out.push_back(r[4]); break;
      case kInclination: out.push_back(s.inclination_rad); break;
      case kNormalToVorticity: out.push_back(s.normal_to_vorticity_rad); break;
      default: out.push_back(s.marker_phase_rad); break;
    }
  }
  return out;
}

double TubeCellSeries::steady_window_s() const {
  const double spin_up = kSpinUpTimes * config_.radius_m * config_.radius_m / config_.kinematic_viscosity_m2_s;
  const double period = jeffery_period_s(config_);
  // A stage that starts from a cell already found steady over a Jeffery period only has its fluid to settle again.
  return std::isfinite(period) && !config_.starts_steady ? std::max(spin_up, period) : spin_up;
}

bool TubeCellSeries::settled() const {
  // Each set-up settles on what the dataset takes from it: Cd from the drag run; DI and Cl from the lift run (the
  // lift run's Cd is the small difference of large forces at a small slip, measured +-10 % at r* 0.7).
  if (config_.setup == TubeCellSetup::drag) return signal_settled(column(kCd), config_.settle_spread, 0.0, false);
  // Cl near the axis fluctuates about a small mean, where a relative spread means nothing: its floor is the lift
  // of 1 % of the Stokes drag 3 pi mu d_p u(r) on the volume-equivalent sphere, 0.01 x 24 / Re_p in Cl units.
  const double u = samples_.empty() ? 0.0 : undisturbed_speed_m_s(samples_.back());
  const double re_p = common::particle_reynolds(particle_diameter_m_, u, config_.kinematic_viscosity_m2_s);
  const double cl_floor = re_p > 0.0 ? 0.01 * 24.0 / re_p : 0.0;
  return signal_settled(column(kDi), config_.settle_spread, 0.0, false) &&
         signal_settled(column(kCl), config_.lift_settle_spread, cl_floor, true);
}

std::size_t TubeCellSeries::transient_samples() const {
  // The first quarter of the series, and at least the config's transient_s (kMembraneTransientTimes membrane relaxation
  // times, during which the cell keeps close to its rest shape, DI ~0.50, whatever the flow: docs/resolved-coupling.md
  // "The membrane transient"; a few spin-ups for a stage that starts from a settled membrane).
  const double transient_s = config_.transient_s;
  return std::max(static_cast<std::size_t>(kTransientFraction * static_cast<double>(samples_.size())),
                  static_cast<std::size_t>(std::ceil(transient_s / config_.sample_every_s)));
}

bool TubeCellSeries::signal_settled(const std::vector<double>& signal, double spread, double floor, bool noisy) const {
  const std::size_t skip = transient_samples();
  if (skip >= signal.size()) return false;
  const std::vector<double> settled_part(signal.begin() + static_cast<std::ptrdiff_t>(skip), signal.end());
  // Periodic: settle_periods whole periods after the transient agree within `spread`.
  if (has_settled(settled_part, config_.sample_every_s, config_.settle_periods, 0.0, spread, floor)) return true;
  // Steady (not periodic) motion: constant within `spread` over a window that spans the spin-up and one Jeffery
  // period, so a slow tumble cannot pass for steady; the window is at most half the part after the transient. A
  // noisy signal is judged by the means of the window's thirds, a smooth one by its whole range.
  const auto window = static_cast<std::size_t>(std::ceil(steady_window_s() / config_.sample_every_s));
  if (window < 6 || 2 * window > settled_part.size()) return false;
  return (noisy ? trailing_thirds_spread(settled_part, window, floor) : trailing_relative_range(settled_part, window, floor)) <=
         spread;
}

nlohmann::json TubeCellSeries::results() const {
  nlohmann::json r;
  if (samples_.empty()) return r;
  const double dt = config_.sample_every_s;
  // Averages over the part after the transient; a run stopped before it ends (a cap, a quick run) uses all of it.
  const std::size_t skip = transient_samples() + 8 <= samples_.size() ? transient_samples() : 0;
  const auto after = [skip](std::vector<double> v) { return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(skip), v.end()); };
  const auto di = after(column(kDi));
  const auto cd = after(column(kCd));
  const auto cl = after(column(kCl));
  PeriodEstimate period = detect_period(di, dt);
  if (!period.periodic && !period.steady) period = detect_period(cd, dt);
  const auto a_di = average_over_periods(di, dt, period, config_.settle_periods);
  const auto a_cd = average_over_periods(cd, dt, period, config_.settle_periods);
  const auto a_cl = average_over_periods(cl, dt, period, config_.settle_periods);
  const auto inclination = after(column(kInclination));
  const auto phase = after(column(kPhase));
  // Undisturbed flow and groups at the mean (last-sample) position of the centre of mass.
  const TubeCellSample& last = samples_.back();
  const double r_m = radial_m(last);
  const double nu = config_.kinematic_viscosity_m2_s;
  const double mu = nu * config_.density_kg_m3;
  const double gamma = common::poiseuille_shear_rate(config_.u_max_m_s, r_m, config_.radius_m);
  const double u_fluid = common::poiseuille_velocity(config_.u_max_m_s, r_m, config_.radius_m);
  const double u_mean = 0.5 * config_.u_max_m_s;
  r["di_mean"] = a_di.mean;
  r["di_spread"] = a_di.spread;
  r["cd_mean"] = a_cd.mean;
  r["cd_spread"] = a_cd.spread;
  r["cl_mean"] = a_cl.mean;
  r["cl_spread"] = a_cl.spread;
  r["periods_averaged"] = a_di.periods;
  r["period_s"] = period.period_s;
  r["periodic"] = period.periodic;
  r["steady"] = period.steady;
  r["flow_mode"] = to_string(classify_flow_mode(inclination, phase));
  // The long axis' inclination cannot tell a rolling disc from a tumbling one (both turn it in the shear plane).
  // Samples restored from checkpoints older than the measure have none (NaN): the mean skips them.
  const double normal_to_vorticity = finite_mean(after(column(kNormalToVorticity)));
  r["disc_orientation"] = classify_disc_orientation(normal_to_vorticity);
  r["normal_to_vorticity_deg_mean"] = normal_to_vorticity * 180.0 / std::numbers::pi;
  r["averages"] = {{"di", average_json(a_di)}, {"cd", average_json(a_cd)}, {"cl", average_json(a_cl)}};
  r["reynolds"] = common::channel_reynolds(config_.density_kg_m3, 2.0 * config_.radius_m, config_.u_max_m_s, mu);
  r["r_star"] = r_m / config_.radius_m;
  r["r_star_nominal"] = config_.radial_position;
  r["gamma_plus"] = common::shear_rate_plus(gamma, config_.radius_m, nu);
  r["u_r_plus"] = common::slip_velocity_plus(last.axial_velocity_m_s, u_fluid, u_mean);
  r["re_p"] = common::particle_reynolds(particle_diameter_m_, last.axial_velocity_m_s - u_fluid, nu);
  r["ca"] = common::capillary_number(mu, gamma, 0.5 * kCellDiameterD0_m, config_.membrane.material.shear_modulus_N_m);
  r["particle_diameter_m"] = particle_diameter_m_;
  r["shear_rate_1_s"] = gamma;
  r["membrane_relaxation_time_s"] = membrane_relaxation_time_s(config_);
  r["transient_s"] = static_cast<double>(skip) * dt;   // start of the averaged part (0: the run ended inside the transient)
  r["undisturbed_velocity_m_s"] = u_fluid;
  r["u_max_m_s"] = config_.u_max_m_s;
  r["samples"] = samples_.size();
  return r;
}

}  // namespace hs::resolved
