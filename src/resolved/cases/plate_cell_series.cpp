// SPDX-License-Identifier: MIT
// The sampled time series of a shear or migration run and its reduction to results and dimensionless groups.
#include "resolved/cases/plate_cell_series.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/dimensionless_groups.hpp"
#include "resolved/measure/flow_mode.hpp"
#include "resolved/measure/whole_revolutions.hpp"

namespace hs::resolved {
namespace {

constexpr std::size_t kOldPackedFields = 10;   // checkpoints before the energy books: no header, 10 fields a sample
constexpr std::size_t kEnergyPackedFields = 19;   // checkpoints with the energy books, before the stresslet
constexpr std::size_t kStressletPackedFields = 21;   // with the stresslet and volume, before the Taylor deformation
constexpr std::size_t kPackedFields = 22;      // now: a header -kPackedFields (a time is never negative), then samples
/// Share of the series treated as start-up before averages (mean inclination, DI, tank-treading rate) are taken.
constexpr double kTransientFraction = 0.5;

/// The last two whole revolutions of the marker taking the same time as the two before within this share make a settled
/// tank-treading state: the 2 % of #26's criterion for what numerical knobs may change in the frequency.
constexpr double kRevolutionTolerance = 0.02;

/// A run that stops when settled runs at least this long: the flow mode needs two Jeffery periods after the transient
/// half to tell tumbling from tank-treading (plate_cell_checks).
constexpr double kMinJefferyPeriodsToStop = 4.0;

std::size_t first_settled(std::size_t n) { return static_cast<std::size_t>(std::floor(kTransientFraction * static_cast<double>(n))); }

/// Tank-treading or swinging (the classifier's "intermediate" when the inclination swings by more than its limit): the
/// membrane revolves about a body that does not tumble. Both are the tank-treading cells of the experiments. The one
/// definition behind the results' `membrane_tank_treads` and the stopping test.
bool membrane_tank_treads(FlowMode mode, const WholeRevolutions& revolutions) {
  return mode != FlowMode::tumbling && mode != FlowMode::steady && !revolutions.periods_s.empty();
}

}  // namespace

TumblingPeriod tumbling_period(std::span<const double> time_s, std::span<const double> inclination_rad) {
  std::vector<double> phi(inclination_rad.begin(), inclination_rad.end());
  unwrap(phi, std::numbers::pi);
  std::vector<double> crossings;
  for (std::size_t i = 1; i < phi.size(); ++i) {
    // Levels (k + 1/2) pi: the long axis across the flow, the fast part of a Jeffery orbit (sharp crossings).
    const double a = phi[i - 1] / std::numbers::pi - 0.5;
    const double b = phi[i] / std::numbers::pi - 0.5;
    if (std::floor(a) == std::floor(b)) continue;
    const double level = std::max(std::floor(a), std::floor(b));
    const double w = (level - a) / (b - a);
    crossings.push_back(time_s[i - 1] + w * (time_s[i] - time_s[i - 1]));
  }
  if (crossings.size() < 2) return {};
  const int half_turns = static_cast<int>(crossings.size()) - 1;
  return {.period_s = 2.0 * (crossings.back() - crossings.front()) / half_turns, .half_turns = half_turns};
}

std::vector<std::string> PlateCellSeries::columns() {
  return {"time_s", "di", "inclination_rad", "marker_phase_rad", "centroid_x_m", "centroid_y_m", "centroid_z_m",
          "y_over_h", "velocity_x_m_s", "velocity_y_m_s", "membrane_fluid_power_W", "membrane_viscous_power_W",
          "membrane_elastic_energy_J", "membrane_kinetic_energy_J", "di_gyration", "stresslet_xy_N_m",
          "taylor_deformation"};
}

std::vector<double> PlateCellSeries::row(std::size_t i) const {
  const PlateCellSample& s = samples_.at(i);
  const MembraneEnergySnapshot before = i > 0 ? samples_[i - 1].energy : MembraneEnergySnapshot{};
  const MembraneEnergyBalance b = membrane_energy_balance(before, s.energy);
  return {s.time_s, s.di, s.inclination_rad, s.marker_phase_rad, s.centroid_m.x, s.centroid_m.y, s.centroid_m.z,
          s.centroid_m.y / config_.gap_m, s.velocity_m_s.x, s.velocity_m_s.y, b.mean_fluid_power_W(),
          b.mean_viscous_power_W(), s.energy.elastic_energy_J, s.energy.kinetic_energy_J, s.di_gyration,
          s.stresslet_xy_N_m, s.taylor_deformation};
}

std::vector<double> PlateCellSeries::pack() const {
  std::vector<double> out;
  out.reserve(1 + kPackedFields * samples_.size());
  out.push_back(-static_cast<double>(kPackedFields));
  for (const auto& s : samples_) {
    const MembraneEnergySnapshot& e = s.energy;
    out.insert(out.end(), {s.time_s, s.di, s.inclination_rad, s.marker_phase_rad, s.centroid_m.x, s.centroid_m.y,
                           s.centroid_m.z, s.velocity_m_s.x, s.velocity_m_s.y, s.velocity_m_s.z, e.external_work_J,
                           e.viscous_dissipation_J, e.damping_dissipation_J, e.elastic_work_J, e.kinetic_step_loss_J,
                           e.solver_residual_work_J, e.elastic_energy_J, e.kinetic_energy_J, s.di_gyration,
                           s.stresslet_xy_N_m, s.volume_m3, s.taylor_deformation});
  }
  return out;
}

void PlateCellSeries::unpack(std::span<const double> flat) {
  samples_.clear();
  // Four layouts: now (header -22), without the Taylor deformation (-21), with the energy books but no stresslet (-19),
  // older (no header).
  const bool header = !flat.empty() && (flat[0] == -static_cast<double>(kPackedFields) ||
                                        flat[0] == -static_cast<double>(kStressletPackedFields) ||
                                        flat[0] == -static_cast<double>(kEnergyPackedFields));
  const std::size_t fields = header ? static_cast<std::size_t>(-flat[0]) : kOldPackedFields;
  for (std::size_t k = header ? 1 : 0; k + fields <= flat.size(); k += fields) {
    const double* v = flat.data() + k;
    PlateCellSample s{.time_s = v[0], .di = v[1], .di_gyration = 0.0, .inclination_rad = v[2], .marker_phase_rad = v[3],
                      .centroid_m = {v[4], v[5], v[6]}, .velocity_m_s = {v[7], v[8], v[9]}, .energy = {}};
    if (header) {
      s.energy = {.time_s = v[0], .external_work_J = v[10], .viscous_dissipation_J = v[11],
                  .damping_dissipation_J = v[12], .elastic_work_J = v[13], .kinetic_step_loss_J = v[14],
                  .solver_residual_work_J = v[15], .elastic_energy_J = v[16], .kinetic_energy_J = v[17]};
      s.di_gyration = v[18];
    }
    if (fields >= kStressletPackedFields) {
      s.stresslet_xy_N_m = v[19];
      s.volume_m3 = v[20];
    }
    if (fields == kPackedFields) s.taylor_deformation = v[21];
    samples_.push_back(s);
  }
}

nlohmann::json PlateCellSeries::energy_results() const {
  const auto to_json = [](const MembraneEnergyBalance& b) {
    return nlohmann::json{{"duration_s", b.duration_s},
                          {"fluid_work_J", b.fluid_work_J},
                          {"viscous_dissipation_J", b.viscous_dissipation_J},
                          {"damping_dissipation_J", b.damping_dissipation_J},
                          {"elastic_energy_change_J", b.elastic_energy_change_J},
                          {"kinetic_energy_change_J", b.kinetic_energy_change_J},
                          {"balance_residual_J", b.balance_residual_J},
                          {"relative_residual", b.relative_residual()},
                          {"implicit_step_loss_J", b.implicit_step_loss_J},
                          {"solver_residual_work_J", b.solver_residual_work_J},
                          {"books_error_J", b.books_error_J},
                          {"mean_fluid_power_W", b.mean_fluid_power_W()},
                          {"mean_viscous_power_W", b.mean_viscous_power_W()}};
  };
  nlohmann::json r;
  if (samples_.empty()) return r;
  // The stored energies are sampled from the first sample on (not at t = 0): the whole-run window starts there.
  r["whole_run"] = to_json(membrane_energy_balance(samples_.front().energy, samples_.back().energy));
  const std::size_t from = first_settled(samples_.size());
  if (from + 1 < samples_.size()) {
    r["second_half"] = to_json(membrane_energy_balance(samples_[from].energy, samples_.back().energy));
  }
  r["note"] = "fluid work = viscous + damping dissipation + change of elastic + kinetic energy + balance residual; "
              "the residual is implicit Euler's loss + the minimisation's residual work (+ books error, round-off); "
              "closed for a free membrane without the friction (docs/resolved-coupling.md, \"Power balance\")";
  return r;
}

nlohmann::json PlateCellSeries::groups() const {
  const double nu = config_.kinematic_viscosity_m2_s;
  const double mu = nu * config_.density_kg_m3;
  const double k_s = config_.membrane.material.shear_modulus_N_m;
  nlohmann::json g;
  g["reynolds"] = config_.reynolds;
  g["shear_rate_1_s"] = config_.shear_rate_1_s;
  g["ca"] = common::capillary_number(mu, config_.shear_rate_1_s, kCellRadius_m, k_s);
  g["particle_reynolds"] = config_.shear_rate_1_s * kCellRadius_m * kCellRadius_m / nu;   // gamma a^2 / nu
  g["confinement"] = 2.0 * kCellRadius_m / config_.gap_m;
  g["u_max_m_s"] = config_.u_max_m_s;
  return g;
}

bool PlateCellSeries::tank_treading_settled() const {
  const std::size_t n = samples_.size();
  if (n < 4 || samples_.back().time_s < kMinJefferyPeriodsToStop * jeffery_period(config_.shear_rate_1_s)) return false;
  const std::size_t from = first_settled(n);
  std::vector<double> t, incl, phase, di;
  for (const auto& s : samples_) {
    t.push_back(s.time_s);
    incl.push_back(s.inclination_rad);
    phase.push_back(s.marker_phase_rad);
    di.push_back(s.di);
  }
  const FlowMode mode = classify_flow_mode(std::span(incl).subspan(from), std::span(phase).subspan(from));
  unwrap(phase, 2.0 * std::numbers::pi);
  const WholeRevolutions rev = whole_revolutions(t, phase, from);
  return membrane_tank_treads(mode, rev) && rev.settled(kRevolutionTolerance, t, di);
}

nlohmann::json PlateCellSeries::results() const {
  nlohmann::json r = config_.flow == PlateFlow::shear ? shear_results() : migration_results();
  r.update(groups());
  r["samples"] = samples_.size();
  return r;
}

nlohmann::json PlateCellSeries::shear_results() const {
  nlohmann::json r;
  std::vector<double> t, incl, phase, di, di_gyration;
  for (const auto& s : samples_) {
    t.push_back(s.time_s);
    incl.push_back(s.inclination_rad);
    phase.push_back(s.marker_phase_rad);
    di.push_back(s.di);
    di_gyration.push_back(s.di_gyration);
  }
  // The mode is read after the release transient (the second half, as the means below): a tank-treading cell released
  // edge-on first turns to its inclination, which the whole-run angle range would count as swinging.
  const std::size_t from = first_settled(samples_.size());
  const FlowMode mode = samples_.size() < 2 || from + 1 >= samples_.size()
                            ? classify_flow_mode(incl, phase)
                            : classify_flow_mode(std::span(incl).subspan(from), std::span(phase).subspan(from));
  const TumblingPeriod tumble = tumbling_period(t, incl);
  const double jeffery = jeffery_period(config_.shear_rate_1_s);
  r["flow_mode"] = to_string(mode);
  r["tumbling_period_s"] = tumble.period_s;
  r["tumbling_half_turns"] = tumble.half_turns;
  r["jeffery_period_s"] = jeffery;
  r["tumbling_period_over_jeffery"] = tumble.period_s / jeffery;
  if (samples_.size() < 2 || from + 1 >= samples_.size()) return r;
  // Mean inclination and DI over the second half; the marker's mean angular rate there is the tank-treading rate.
  double sum_incl = 0.0, sum_di = 0.0, sum_di_gyration = 0.0, sum_taylor = 0.0;
  for (std::size_t i = from; i < samples_.size(); ++i) {
    sum_incl += incl[i];
    sum_di += di[i];
    sum_di_gyration += di_gyration[i];
    sum_taylor += samples_[i].taylor_deformation;
  }
  const double n = static_cast<double>(samples_.size() - from);
  unwrap(phase, 2.0 * std::numbers::pi);
  const double rate = (phase.back() - phase[from]) / (t.back() - t[from]);
  r["mean_inclination_rad"] = sum_incl / n;
  r["mean_inclination_deg"] = sum_incl / n * 180.0 / std::numbers::pi;
  r["di_mean"] = sum_di / n;
  r["di_gyration_mean"] = sum_di_gyration / n;   // from the gyration radii: not set by single vertices (#26)
  r["taylor_deformation_mean"] = sum_taylor / n;  // the equivalent ellipsoid's, in the shear plane (capsule benchmarks)
  // Whether that D is steady: its mean over the last quarter of the run against the quarter before (a capsule's steady
  // state has no whole revolutions of the body to wait for; its membrane's can take longer than its shape).
  const std::size_t third_quarter = (3 * samples_.size()) / 4;
  double sum_q3 = 0.0, sum_q4 = 0.0;
  for (std::size_t i = from; i < samples_.size(); ++i) (i < third_quarter ? sum_q3 : sum_q4) += samples_[i].taylor_deformation;
  const double q3 = sum_q3 / static_cast<double>(std::max<std::size_t>(1, third_quarter - from));
  const double q4 = sum_q4 / static_cast<double>(std::max<std::size_t>(1, samples_.size() - third_quarter));
  r["taylor_deformation_last_quarter_change"] = q3 > 0.0 ? q4 / q3 - 1.0 : 0.0;
  r["tank_treading_frequency_hz"] = mode == FlowMode::tank_treading ? std::abs(rate) / (2.0 * std::numbers::pi) : 0.0;
  r["marker_rate_rad_s"] = rate;
  // The cell's share of the suspension's shear stress: [eta] = <S_xy> / (mu gamma_dot V), so that a dilute
  // suspension at volume fraction phi has eta_r = 1 + [eta] phi (Batchelor 1970; Einstein's 2.5 for a rigid sphere).
  double sum_s = 0.0, sum_v = 0.0;
  for (std::size_t i = from; i < samples_.size(); ++i) {
    sum_s += samples_[i].stresslet_xy_N_m;
    sum_v += samples_[i].volume_m3;
  }
  const double mu = config_.density_kg_m3 * config_.kinematic_viscosity_m2_s;
  r["stresslet_xy_mean_N_m"] = sum_s / n;
  r["intrinsic_viscosity"] = sum_v > 0.0 ? (sum_s / n) / (mu * config_.shear_rate_1_s * sum_v / n) : 0.0;
  r["period_s"] = mode == FlowMode::tumbling ? tumble.period_s
                  : (mode == FlowMode::tank_treading && rate != 0.0 ? 2.0 * std::numbers::pi / std::abs(rate) : 0.0);
  settled_tank_treading(mode, t, phase, di, from, r);
  return r;
}

void PlateCellSeries::settled_tank_treading(FlowMode mode, std::span<const double> t, std::span<const double> phase,
                                            std::span<const double> di, std::size_t from, nlohmann::json& r) const {
  // The whole revolutions of the marker after the transient: settled when the last two take as long as the two before
  // and the cell's mean DI over them is that over the two before, and the window of the means a validation compares
  // (whole revolutions: whole swings of the inclination and the DI).
  const WholeRevolutions rev = whole_revolutions(t, phase, from);
  const bool tank_treading = membrane_tank_treads(mode, rev);
  r["membrane_tank_treads"] = tank_treading;
  r["revolution_periods_s"] = rev.periods_s;
  r["tank_treading_settled"] = tank_treading && rev.settled(kRevolutionTolerance, t, di);
  r["tank_treading_settled_tolerance"] = kRevolutionTolerance;
  const double rate = tank_treading ? rev.rate_rad_s() : 0.0;
  r["tank_treading_frequency_settled_hz"] = rate / (2.0 * std::numbers::pi);
  r["tank_treading_frequency_over_shear_rate"] = rate / (2.0 * std::numbers::pi) / config_.shear_rate_1_s;
  double sum_incl = 0.0, sum_di = 0.0, sum_taylor = 0.0, n = 0.0;
  double incl_min = 0.0, incl_max = 0.0;
  for (const auto& s : samples_) {
    if (s.time_s < rev.window_start_s || s.time_s > rev.window_end_s) continue;
    incl_min = n > 0.0 ? std::min(incl_min, s.inclination_rad) : s.inclination_rad;
    incl_max = n > 0.0 ? std::max(incl_max, s.inclination_rad) : s.inclination_rad;
    sum_incl += s.inclination_rad;
    sum_di += s.di;
    sum_taylor += s.taylor_deformation;
    n += 1.0;
  }
  // Half the range of the outline's angle over whole revolutions (a swinging cell swings twice per revolution).
  r["swinging_amplitude_deg"] = 0.5 * (incl_max - incl_min) * 180.0 / std::numbers::pi;
  const double di_window = n > 0.0 ? sum_di / n : r.value("di_mean", 0.0);
  r["mean_inclination_settled_deg"] = n > 0.0 ? sum_incl / n * 180.0 / std::numbers::pi : r.value("mean_inclination_deg", 0.0);
  r["di_settled"] = di_window;
  r["taylor_deformation_settled"] = n > 0.0 ? sum_taylor / n : r.value("taylor_deformation_mean", 0.0);
  r["settled_window_s"] = {rev.window_start_s, rev.window_end_s};
  // The bound of the measured axes: DI's longest and shortest extents, which for a tank-treading RBC both lie in the
  // shear plane (its axis of symmetry turns into that plane).
  r["keller_skalak_bound_rad_s"] = keller_skalak_bound(config_.shear_rate_1_s, di_window);
}

nlohmann::json PlateCellSeries::migration_results() const {
  nlohmann::json r;
  if (samples_.empty()) return r;
  const double h = config_.gap_m;
  const auto offset = [h](const PlateCellSample& s) { return std::abs(s.centroid_m.y - 0.5 * h) / h; };
  const PlateCellSample& first = samples_.front();
  const PlateCellSample& last = samples_.back();
  r["initial_height"] = config_.initial_height;
  r["final_y_over_h"] = last.centroid_m.y / h;
  r["initial_offset_over_h"] = std::abs(config_.initial_height - 0.5);
  r["final_offset_over_h"] = offset(last);
  // Mean lateral speed toward the centreline, over the whole run (positive: toward the centre).
  const double span_s = last.time_s - first.time_s;
  const double toward_m = (std::abs(config_.initial_height - 0.5) - offset(last)) * h;
  r["migration_speed_m_s"] = last.time_s > 0.0 ? toward_m / last.time_s : 0.0;
  r["migration_speed_over_u_max"] = last.time_s > 0.0 ? toward_m / last.time_s / config_.u_max_m_s : 0.0;
  r["sampled_span_s"] = span_s;
  r["moved_toward_centre"] = toward_m > 0.0;
  // Lateral position at quarters of the run, for the note and the plot legend.
  nlohmann::json at = nlohmann::json::array();
  for (const double f : {0.25, 0.5, 0.75, 1.0}) {
    const auto idx = std::min(samples_.size() - 1,
                              static_cast<std::size_t>(std::lround(f * static_cast<double>(samples_.size() - 1))));
    at.push_back({{"time_s", samples_[idx].time_s}, {"y_over_h", samples_[idx].centroid_m.y / h}});
  }
  r["lateral_position"] = at;
  // Time at which the offset from the centreline first falls to half its initial value (linear interpolation
  // between samples; 0 if it never does): a rate that does not depend on how long the run went on settling.
  const double half = 0.5 * std::abs(config_.initial_height - 0.5);
  double t_half = 0.0;
  for (std::size_t i = 1; i < samples_.size() && t_half == 0.0; ++i) {
    const double a = offset(samples_[i - 1]);
    const double b = offset(samples_[i]);
    if (a > half && b <= half) {
      t_half = samples_[i - 1].time_s + (a - half) / (a - b) * (samples_[i].time_s - samples_[i - 1].time_s);
    }
  }
  r["half_offset_time_s"] = t_half;
  const double mu = config_.density_kg_m3 * config_.kinematic_viscosity_m2_s;
  const double gamma0 = 4.0 * config_.u_max_m_s * std::abs(1.0 - 2.0 * config_.initial_height) / h;   // |du/dy| at y0
  r["ca_initial"] = common::capillary_number(mu, gamma0, kCellRadius_m, config_.membrane.material.shear_modulus_N_m);
  r["mean_axial_velocity_over_u_max"] = last.velocity_m_s.x / config_.u_max_m_s;
  return r;
}

}  // namespace hs::resolved
