// SPDX-License-Identifier: MIT
// Hertz normal contact with restitution damping and history (Mindlin) tangential friction, in the
// LIGGGHTS form (pair_style gran model hertz tangential history), reduced to per-pair constants.
#pragma once

#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {

/// Constants of one material pair (particle-particle or particle-wall). Sources: unresolved-methods.md
/// 4.1-4.4, after LIGGGHTS normal_model_hertz.h, tangential_model_history.h and global_properties.cpp.
struct PairConstants {
  double y_eff_Pa;        // Y* = 1 / [(1 - nu_i^2)/Y_i + (1 - nu_j^2)/Y_j]
  double g_eff_Pa;        // G* = 1 / [2 (2 - nu_i)(1 + nu_i)/Y_i + 2 (2 - nu_j)(1 + nu_j)/Y_j]
  double beta;            // ln e / sqrt(ln^2 e + pi^2)  (<= 0)
  double friction;        // Coulomb coefficient, mean of the two materials' values
  /// gamma_n = damping_n * sqrt(m* sqrt(R* delta)), i.e. -2 sqrt(5/6) beta sqrt(2 Y*) (likewise for t, 8 G*).
  double damping_n;
  double damping_t;
};

class HertzContactLaw {
 public:
  explicit HertzContactLaw(const ParticleParams& params);

  [[nodiscard]] const PairConstants& particle_particle() const { return pp_; }
  [[nodiscard]] const PairConstants& particle_wall() const { return pw_; }
  [[nodiscard]] bool limit_normal_force() const { return limit_normal_force_; }

  /// Combines two materials by the rules of LIGGGHTS global_properties.cpp.
  [[nodiscard]] static PairConstants combine(const Material& a, const Material& b);

 private:
  PairConstants pp_;
  PairConstants pw_;
  bool limit_normal_force_;
};

/// Hertz collision time t_H = 2.87 (m*^2 / (R* Y*^2 v))^(1/5) of a particle hitting its twin at speed v
/// (LIGGGHTS fix check/timestep/gran; unresolved-methods.md 4.5).
[[nodiscard]] double hertz_time_s(const ParticleParams& params, double impact_velocity_m_s);
/// Rayleigh time t_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / (2 (1 + nu)) (Li, Xu & Thornton 2005).
[[nodiscard]] double rayleigh_time_s(const ParticleParams& params);
/// Throws ConfigError unless dt_s <= 0.1 min(t_R, t_H(v_max)) (the criterion of the seed paper, sec. 2.2).
void check_time_step(const ParticleParams& params, double dt_s);

}  // namespace hs::unresolved
