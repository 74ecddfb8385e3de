// SPDX-License-Identifier: MIT
#include "resolved/cases/stokes_analogue.hpp"

#include <numbers>

namespace hs::resolved {

double cell_stokes_number(double mass_kg, double shear_rate_1_s, double viscosity_Pa_s, double radius_m) {
  return mass_kg * shear_rate_1_s / (6.0 * std::numbers::pi * viscosity_Pa_s * radius_m);
}

double stokes_analogue_viscosity_factor(const StokesAnalogueInput& in) {
  const double a = in.cell_radius_m;
  const double re_p = in.shear_rate_1_s * a * a / in.kinematic_viscosity_m2_s;
  const double stokes =
      cell_stokes_number(in.cell_mass_kg, in.shear_rate_1_s, in.density_kg_m3 * in.kinematic_viscosity_m2_s, a);
  // At fixed Ca the shear rate goes as 1 / factor: Re_p and St both as 1 / factor^2.
  double factor = 1.0;
  while (re_p / (factor * factor) > kAnalogueMaxParticleReynolds || stokes / (factor * factor) > kAnalogueMaxCellStokes) {
    factor *= 2.0;
  }
  return factor;
}

}  // namespace hs::resolved
