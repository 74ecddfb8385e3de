// SPDX-License-Identifier: MIT
// The dimensionless groups of hemoscale, defined once: the resolved stage measures them, the closures take
// them, the unresolved stage computes them from its fields. One definition keeps the three consistent.
#pragma once

namespace hs::common {

/// Channel Reynolds number Re = rho D U_max / mu (seed paper section 4.1; D the tube diameter).
constexpr double channel_reynolds(double density_kg_m3, double diameter_m, double max_velocity_m_s,
                                  double dynamic_viscosity_Pa_s) {
  return density_kg_m3 * diameter_m * max_velocity_m_s / dynamic_viscosity_Pa_s;
}

/// Dimensionless shear rate gamma+ = gamma_dot R_c^2 / nu (seed paper section 4; R_c the channel radius).
constexpr double shear_rate_plus(double shear_rate_1_s, double channel_radius_m, double kinematic_viscosity_m2_s) {
  return shear_rate_1_s * channel_radius_m * channel_radius_m / kinematic_viscosity_m2_s;
}

/// Dimensionless slip u_r+ = (u_p - u) / u_av: particle minus undisturbed fluid velocity at the particle
/// centre, over the mean channel velocity (seed paper section 4). Signed: negative when the cell lags the flow.
constexpr double slip_velocity_plus(double particle_velocity_m_s, double fluid_velocity_m_s, double mean_velocity_m_s) {
  return (particle_velocity_m_s - fluid_velocity_m_s) / mean_velocity_m_s;
}

/// Particle Reynolds number Re_p = d_p |u_p - u| / nu, with d_p the volume-equivalent sphere diameter.
constexpr double particle_reynolds(double particle_diameter_m, double slip_speed_m_s, double kinematic_viscosity_m2_s) {
  return particle_diameter_m * (slip_speed_m_s < 0 ? -slip_speed_m_s : slip_speed_m_s) / kinematic_viscosity_m2_s;
}

/// Capillary number Ca = mu gamma_dot a / k_s (a the cell radius, k_s the membrane shear modulus).
constexpr double capillary_number(double dynamic_viscosity_Pa_s, double shear_rate_1_s, double cell_radius_m,
                                  double shear_modulus_N_m) {
  return dynamic_viscosity_Pa_s * shear_rate_1_s * cell_radius_m / shear_modulus_N_m;
}

/// Force coefficient C = F / (1/2 rho U^2 pi d^2 / 4): drag and lift alike, with U the relative speed
/// |u - u_p| and d the volume-equivalent sphere diameter (docs/coefficients.md).
constexpr double force_coefficient(double force_N, double density_kg_m3, double relative_speed_m_s, double diameter_m) {
  constexpr double pi = 3.14159265358979323846;
  return force_N / (0.5 * density_kg_m3 * relative_speed_m_s * relative_speed_m_s * pi * diameter_m * diameter_m / 4.0);
}

/// Hagen–Poiseuille profile in a tube: u(r) = U_max (1 - r^2/R^2), shear rate |du/dr| = 2 U_max r / R^2.
constexpr double poiseuille_velocity(double max_velocity_m_s, double r_m, double radius_m) {
  return max_velocity_m_s * (1.0 - r_m * r_m / (radius_m * radius_m));
}
constexpr double poiseuille_shear_rate(double max_velocity_m_s, double r_m, double radius_m) {
  return 2.0 * max_velocity_m_s * r_m / (radius_m * radius_m);
}

}  // namespace hs::common
