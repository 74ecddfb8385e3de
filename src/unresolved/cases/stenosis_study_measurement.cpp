// SPDX-License-Identifier: MIT
// The stenosis study's per-step sums along the axis and the hemolysis index per cell.
#include "unresolved/cases/stenosis_study_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "common/dimensionless_groups.hpp"
#include "unresolved/coupling/shear_rate.hpp"
#include "unresolved/cases/closure_validity_report.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

constexpr std::size_t kPerBin = 8;
constexpr std::size_t kCells = 0, kDiSum = 1, kDiSq = 2, kUx = 3, kRbc = 4, kOutDi = 5, kOutAny = 6, kWallShear = 7;

/// The closures' inputs at owned particle i, as CfdDemCoupling::inputs forms them (cfd_dem_coupling.cpp: slip from
/// the fluid velocity at the centre, shear rate of its gradient, R_c and u_av from the channel frame).
hs::closures::ClosureInputs closure_inputs(const ParticleStore& p, std::size_t i, const FvmSolver& fluid, ChannelFrame& frame) {
  const Vec3 x{p.position_m()[0][i], p.position_m()[1][i], p.position_m()[2][i]};
  const Vec3 v{p.velocity_m_s()[0][i], p.velocity_m_s()[1][i], p.velocity_m_s()[2][i]};
  const Vec3 uf = fluid.velocity_at(x);
  const double nu = fluid.fluid().kinematic_viscosity_m2_s;
  const double d = 2.0 * p.radius_m()[i];
  const double gd = shear_rate(fluid.velocity_gradient_at(x));
  const ChannelFrame::Local local = frame.at(x);
  hs::closures::ClosureInputs in;
  in.re_p = hs::common::particle_reynolds(d, norm(v - uf), nu);
  in.re_shear = gd * d * d / nu;
  in.shear_ratio = in.re_p > 0.0 ? in.re_shear / in.re_p : 0.0;
  in.gamma_plus = hs::common::shear_rate_plus(gd, local.channel_radius_m, nu);
  in.u_r_plus = local.flow.mean_velocity_m_s > 0.0
                    ? hs::common::slip_velocity_plus(dot(v, local.flow.direction), dot(uf, local.flow.direction),
                                                     local.flow.mean_velocity_m_s)
                    : 0.0;
  in.di = p.deformation_index()[i];
  return in;
}

}  // namespace

StenosisStudyMeasurement::StenosisStudyMeasurement(const OpenGeometryConfig& c, StenosisStudySpec spec)
    : base_(c), spec_(std::move(spec)), fluid_stores_(c.model.void_fraction_rate), bin_fluid_m3_(spec_.bin_fluid_m3()),
      outlet_x_m_(0.5 * (spec_.x_lo_m + spec_.x_hi_m)) {
  for (const auto& o : c.openings) {
    if (o.type == hs::common::OpeningFlowType::flow_rate_inlet) inlets_.push_back(o.opening.name);
  }
}

std::vector<std::string> StenosisStudyMeasurement::columns() const {
  std::vector<std::string> cols = base_.columns();
  for (int i = 0; i < spec_.x_bins; ++i) {
    for (const char* what : {"_cells", "_di_sum", "_di_sq_sum", "_ux_sum", "_rbc_m3", "_outside_di", "_outside_any", "_wall_shear_1_s"}) {
      cols.push_back(fmt::format("x{}{}", i, what));
    }
  }
  return cols;
}

void StenosisStudyMeasurement::prepare(CfdDemSolvers& run) {
  base_.prepare(run);
  frame_ = std::make_unique<ChannelFrame>(run.fluid());
}

void StenosisStudyMeasurement::accumulate_hemolysis(const CfdDemSolvers& run) {
  const ParticleStore& p = run.dem().particles();
  const FvmSolver& fluid = run.fluid();
  const double mu = fluid.fluid().density_kg_m3 * fluid.fluid().kinematic_viscosity_m2_s;
  const double dt = fluid.settings().dt_s;
  const double power = spec_.hemolysis.beta / spec_.hemolysis.alpha;
  std::unordered_map<std::int64_t, double> seen;
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const Vec3 x{p.position_m()[0][i], p.position_m()[1][i], p.position_m()[2][i]};
    const std::int64_t id = p.id()[i];
    const double tau = mu * shear_rate(fluid.velocity_gradient_at(x));
    exposure_[id] += std::pow(tau, power) * dt;
    entered_s_.try_emplace(id, fluid.time_s() - dt);
    seen[id] = x.x;
  }
  // A cell seen at the last sample and gone now left the domain: by the outlet when it was past the middle.
  for (const auto& [id, x_last] : last_x_m_) {
    if (seen.count(id) > 0) continue;
    if (x_last > outlet_x_m_) {
      left_index_percent_.push_back(spec_.hemolysis.c_percent * std::pow(exposure_[id], spec_.hemolysis.alpha));
      left_exposure_s_.push_back(fluid.time_s() - entered_s_[id]);
    }
    exposure_.erase(id);
    entered_s_.erase(id);
  }
  last_x_m_ = std::move(seen);
}

std::vector<double> StenosisStudyMeasurement::sample(const CfdDemSolvers& run) {
  std::vector<double> row = base_.sample(run);
  const ParticleStore& p = run.dem().particles();
  const FvmSolver& fluid = run.fluid();
  const CouplingClosures& cl = run.coupling().closures();
  frame_->new_step();
  std::vector<double> bins(kPerBin * static_cast<std::size_t>(spec_.x_bins), 0.0);
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const int b = spec_.bin_of(p.position_m()[0][i]);
    if (b < 0) continue;
    double* h = &bins[kPerBin * static_cast<std::size_t>(b)];
    const double di = p.deformation_index()[i];
    h[kCells] += 1.0;
    h[kDiSum] += di;
    h[kDiSq] += di * di;
    h[kUx] += p.velocity_m_s()[0][i];
    h[kRbc] += 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius_m()[i], 3);
    const hs::closures::ClosureInputs in = closure_inputs(p, i, fluid, *frame_);
    const bool di_ok = cl.deformation == nullptr || cl.deformation->inside(in);
    bool all_ok = di_ok && cl.drag->inside(in);
    if (cl.lift != nullptr) {
      hs::closures::ClosureInputs lift_in = in;   // a lift fitted on the fluid velocity takes its Re_p (the coupling's)
      if (cl.lift->reference_velocity() == hs::closures::LiftVelocity::flow) {
        const Vec3 x{p.position_m()[0][i], p.position_m()[1][i], p.position_m()[2][i]};
        lift_in.re_p = hs::common::particle_reynolds(2.0 * p.radius_m()[i], norm(fluid.velocity_at(x)),
                                                     fluid.fluid().kinematic_viscosity_m2_s);
        lift_in.shear_ratio = lift_in.re_p > 0.0 ? lift_in.re_shear / lift_in.re_p : 0.0;
      }
      all_ok = all_ok && cl.lift->inside(lift_in);
    }
    h[kOutDi] += di_ok ? 0.0 : 1.0;
    h[kOutAny] += all_ok ? 0.0 : 1.0;
  }
  // Wall shear rate half a cell inside the wall, along the wall's inward normal, around the circumference.
  const double delta = 0.5 * run.grid().dx_m();
  const hs::common::ConstrictionProfile profile{spec_.tube.radius_m, spec_.tube.throat_radius_m, spec_.tube.constriction_length_m};
  for (int b = 0; b < spec_.x_bins; ++b) {
    const double x = spec_.bin_centre_m(b);
    const double r = spec_.radius_at(x);
    const double slope = profile.slope(x - spec_.throat_x_m());
    const double norm_len = std::sqrt(1.0 + slope * slope);
    double sum = 0.0;
    for (int k = 0; k < spec_.wall_shear_azimuths; ++k) {
      const double th = 2.0 * std::numbers::pi * (k + 0.5) / spec_.wall_shear_azimuths;
      // Outward normal of r = R(x): (-R'(x), cos th, sin th) / sqrt(1 + R'^2).
      const Vec3 n{-slope / norm_len, std::cos(th) / norm_len, std::sin(th) / norm_len};
      const Vec3 wall{x, spec_.tube.start_m.y + r * std::cos(th), spec_.tube.start_m.z + r * std::sin(th)};
      sum += shear_rate(fluid.velocity_gradient_at(wall - delta * n));
    }
    bins[kPerBin * static_cast<std::size_t>(b) + kWallShear] = sum / spec_.wall_shear_azimuths;
  }
  row.insert(row.end(), bins.begin(), bins.end());
  accumulate_hemolysis(run);
  return row;
}

void StenosisStudyMeasurement::write_state(hs::common::Checkpoint& cp) const {
  base_.write_state(cp);
  std::vector<std::int64_t> ids;
  std::vector<double> exposure;
  std::vector<double> entered;
  std::vector<double> last_x;
  for (const auto& [id, e] : exposure_) {
    ids.push_back(id);
    exposure.push_back(e);
    entered.push_back(entered_s_.at(id));
    last_x.push_back(last_x_m_.count(id) > 0 ? last_x_m_.at(id) : spec_.x_lo_m);
  }
  cp.put("stenosis.ids", ids);
  cp.put("stenosis.exposure", exposure);
  cp.put("stenosis.entered_s", entered);
  cp.put("stenosis.last_x_m", last_x);
  cp.put("stenosis.left_index_percent", left_index_percent_);
  cp.put("stenosis.left_exposure_s", left_exposure_s_);
}

void StenosisStudyMeasurement::read_state(const hs::common::Checkpoint& cp) {
  base_.read_state(cp);
  exposure_.clear();
  entered_s_.clear();
  last_x_m_.clear();
  const auto& ids = cp.integers("stenosis.ids");
  const auto& exposure = cp.doubles("stenosis.exposure");
  const auto& entered = cp.doubles("stenosis.entered_s");
  const auto& last_x = cp.doubles("stenosis.last_x_m");
  for (std::size_t k = 0; k < ids.size(); ++k) {
    exposure_[ids[k]] = exposure[k];
    entered_s_[ids[k]] = entered[k];
    last_x_m_[ids[k]] = last_x[k];
  }
  left_index_percent_ = cp.doubles("stenosis.left_index_percent");
  left_exposure_s_ = cp.doubles("stenosis.left_exposure_s");
}

namespace {

/// Value below which a share q of the sorted values lies (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::clamp(std::ceil(q * static_cast<double>(sorted.size())) - 1.0, 0.0,
                                                     static_cast<double>(sorted.size() - 1)));
  return sorted[k];
}

nlohmann::json distribution(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double mean = 0.0;
  for (const double x : v) mean += x / static_cast<double>(v.size());
  return {{"count", v.size()}, {"mean", mean}, {"median", quantile(v, 0.5)}, {"p10", quantile(v, 0.1)},
          {"p90", quantile(v, 0.9)}, {"p99", quantile(v, 0.99)}, {"min", v.empty() ? 0.0 : v.front()},
          {"max", v.empty() ? 0.0 : v.back()}};
}

}  // namespace

nlohmann::json StenosisStudyMeasurement::summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const {
  nlohmann::json j = base_.summary(run, rows);
  std::vector<double> centres;
  for (int i = 0; i < spec_.x_bins; ++i) centres.push_back(spec_.bin_centre_m(i));
  std::vector<double> radius;
  for (const double x : centres) radius.push_back(spec_.radius_at(x));
  j["results"]["study_layout"] = {
      {"x_bins", spec_.x_bins}, {"x_range_m", {spec_.x_lo_m, spec_.x_hi_m}}, {"bin_centres_m", centres},
      {"wall_radius_m", radius}, {"bin_fluid_m3", bin_fluid_m3_}, {"throat_x_m", spec_.throat_x_m()},
      {"radius_m", spec_.tube.radius_m}, {"throat_radius_m", spec_.tube.throat_radius_m},
      {"constriction_length_m", spec_.tube.constriction_length_m},
      {"upstream_window_m", spec_.upstream_window_m}, {"downstream_window_m", spec_.downstream_window_m},
      {"inlets", inlets_}, {"fluid_stores", fluid_stores_}, {"dt_s", run.fluid().settings().dt_s},
      {"dx_m", run.grid().dx_m()}, {"dynamic_viscosity_Pa_s", run.fluid().fluid().density_kg_m3 * run.fluid().fluid().kinematic_viscosity_m2_s}};
  j["results"]["closure_validity"] = closure_validity_report(run.coupling().closures());
  j["results"]["hemolysis"] = {
      {"model", "Giersiepen et al. 1990: D = C t^alpha tau^beta (%), linearised along the path (Garon & Farinas 2004): "
                "D = C (sum tau^(beta/alpha) dt)^alpha, tau = mu sqrt(2 S:S) of the plasma at the cell centre"},
      {"c_percent", spec_.hemolysis.c_percent}, {"alpha", spec_.hemolysis.alpha}, {"beta", spec_.hemolysis.beta},
      {"index_percent", distribution(left_index_percent_)}, {"time_in_device_s", distribution(left_exposure_s_)}};
  return j;
}

}  // namespace hs::unresolved
