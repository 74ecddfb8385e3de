// SPDX-License-Identifier: MIT
// Pair constants of the Hertz/history contact law and the DEM time-step criteria.
#include "unresolved/dem/hertz_contact_law.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

// Fraction of min(t_Rayleigh, t_Hertz) allowed for the DEM step: [SEED] sec. 2.2, unresolved-methods.md 4.5.
constexpr double time_step_fraction = 0.1;

}  // namespace

PairConstants HertzContactLaw::combine(const Material& a, const Material& b) {
  const double y_eff = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus_Pa +
                              (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus_Pa);
  const double g_eff = 1.0 / (2.0 * (2.0 - a.poisson_ratio) * (1.0 + a.poisson_ratio) / a.youngs_modulus_Pa +
                              2.0 * (2.0 - b.poisson_ratio) * (1.0 + b.poisson_ratio) / b.youngs_modulus_Pa);
  // LIGGGHTS takes the restitution and friction per type pair; for two materials we use the mean.
  const double e = 0.5 * (a.restitution + b.restitution);
  const double log_e = std::log(e);
  const double beta = log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
  // gamma_n = -2 sqrt(5/6) beta sqrt(S_n m*), S_n = 2 Y* sqrt(R* delta): the constant part below.
  const double c = -2.0 * std::sqrt(5.0 / 6.0) * beta;
  return {.y_eff_Pa = y_eff,
          .g_eff_Pa = g_eff,
          .beta = beta,
          .friction = 0.5 * (a.friction + b.friction),
          .damping_n = c * std::sqrt(2.0 * y_eff),
          .damping_t = c * std::sqrt(8.0 * g_eff)};
}

HertzContactLaw::HertzContactLaw(const ParticleParams& params)
    : pp_(combine(params.particle, params.particle)),
      pw_(combine(params.particle, params.wall)),
      limit_normal_force_(params.limit_normal_force) {}

double hertz_time_s(const ParticleParams& params, double impact_velocity_m_s) {
  const PairConstants c = HertzContactLaw::combine(params.particle, params.particle);
  const double m_eff = 0.5 * params.mass_kg();
  const double r_eff = 0.5 * params.radius_m();
  return 2.87 * std::pow(m_eff * m_eff / (r_eff * c.y_eff_Pa * c.y_eff_Pa * impact_velocity_m_s), 0.2);
}

double rayleigh_time_s(const ParticleParams& params) {
  const double nu = params.particle.poisson_ratio;
  const double shear_modulus_Pa = params.particle.youngs_modulus_Pa / (2.0 * (1.0 + nu));
  return std::numbers::pi * params.radius_m() * std::sqrt(params.density_kg_m3 / shear_modulus_Pa) /
         (0.1631 * nu + 0.8766);
}

void check_time_step(const ParticleParams& params, double dt_s) {
  const double t_r = rayleigh_time_s(params);
  const double t_h = hertz_time_s(params, params.max_impact_velocity_m_s);
  const double limit = time_step_fraction * std::min(t_r, t_h);
  if (!(dt_s > 0.0) || dt_s > limit) {
    throw hs::common::ConfigError(fmt::format(
        "DEM time step {:.4g} s is not in (0, 0.1 x min(Rayleigh time {:.4g} s, Hertz time {:.4g} s at "
        "max_impact_velocity_m_s = {:.3g})] = (0, {:.4g} s]; reduce the DEM time step, or soften "
        "[particles] youngs_modulus_Pa = {:.4g}",
        dt_s, t_r, t_h, params.max_impact_velocity_m_s, limit, params.particle.youngs_modulus_Pa));
  }
}

}  // namespace hs::unresolved
