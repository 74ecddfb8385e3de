// SPDX-License-Identifier: MIT
// The Stokes-flow analogue of a shear case: every viscosity raised by the same power of two until the cell's inertia
// (its Reynolds and Stokes numbers) is negligible, the groups of a Stokes-flow cell (Ca, lambda, Bq) kept.
#pragma once

namespace hs::resolved {

/// Largest particle Reynolds number gamma_dot a^2 / nu of the analogue. Measured (docs/resolved-coupling.md "The
/// Stokes-flow analogue without the cell's inertia"): at 10.7 mPa s, Ca 2.04, St 0.09, Re_p 0.0195 -> 0.0049 moved
/// the mean inclination from 7.0 to 2.7 deg and the swinging from +-10 to +-15 deg; 0.0049 -> 0.0012 moved neither
/// by more than the revolutions' scatter. (At 28.9 mPa s, Ca 11.7, Re_p 0.11 -> 0.028 -> 0.0069: f / gamma_dot 0.0349 ->
/// 0.0261 -> 0.0265, the angle +1.2 deg in the last step.)
inline constexpr double kAnalogueMaxParticleReynolds = 0.005;
/// Largest Stokes number m gamma_dot / (6 pi mu a) of the cell (m: its mass with the numerical mass factor): at 10.7
/// mPa s, Ca 2.04, Re_p 0.0195, St 0.089 / 0.178 / 0.356 gave 7.0 / 6.2 / 1.1 deg; at Re_p 0.0049, St 0.022 / 0.044 /
/// 0.087 gave 2.5 / 2.5 / 2.7 deg, f / gamma_dot 0.0434 / 0.0443 / 0.0427 (measured, same section).
inline constexpr double kAnalogueMaxCellStokes = 0.05;

/// The cell's Stokes number m gamma_dot / (6 pi mu a): its momentum relaxation time (Stokes drag of a sphere of radius
/// a) against the shear time.
[[nodiscard]] double cell_stokes_number(double mass_kg, double shear_rate_1_s, double viscosity_Pa_s, double radius_m);

/// What the analogue starts from: the case's viscosity, the shear rate its Ca gives there, the cell's mass.
struct StokesAnalogueInput {
  double kinematic_viscosity_m2_s = 0.0;
  double density_kg_m3 = 0.0;
  double shear_rate_1_s = 0.0;
  double cell_mass_kg = 0.0;    // with the mass factor
  double cell_radius_m = 0.0;   // a of Ca, Re_p and St
};

/// The smallest factor 2^k (k >= 0) by which every viscosity is multiplied (the shear rate divided, Ca kept) so that
/// Re_p <= kAnalogueMaxParticleReynolds and St <= kAnalogueMaxCellStokes: both fall as the factor squared.
[[nodiscard]] double stokes_analogue_viscosity_factor(const StokesAnalogueInput& in);

}  // namespace hs::resolved
