// SPDX-License-Identifier: MIT
// Material and geometry of the DEM particles (the [particles] case section), in SI units.
#pragma once

#include <numbers>

#include "common/config/config_file.hpp"

namespace hs::unresolved {

/// RBC volume from the Evans-Fung shape integrated in shared/reference/validation/README.md (94.1 um^3;
/// measured 94 +- 14 um^3, Evans & Fung 1972, rbc_blood_properties.csv).
inline constexpr double rbc_volume_m3 = 94.1e-18;

/// Diameter of the sphere of volume `volume_m3`: d = (6 V / pi)^(1/3).
[[nodiscard]] double volume_equivalent_diameter(double volume_m3);

/// Elastic and frictional properties of one material (particle or wall).
struct Material {
  double youngs_modulus_Pa;
  double poisson_ratio;
  double restitution;        // coefficient of restitution e in (0, 1]
  double friction;           // Coulomb coefficient mu_f >= 0
};

struct ParticleParams {
  double diameter_m;
  double density_kg_m3;
  Material particle;
  Material wall;
  double skin_m;                   // Verlet-list skin: list rebuilt when a particle moved skin/2
  double max_impact_velocity_m_s;  // v_max in the Hertz-time estimate (time-step check)
  bool limit_normal_force;         // clip attractive damped normal forces at zero (LIGGGHTS limitForce)

  [[nodiscard]] double radius_m() const { return 0.5 * diameter_m; }
  [[nodiscard]] double volume_m3() const { return std::numbers::pi / 6.0 * diameter_m * diameter_m * diameter_m; }
  [[nodiscard]] double mass_kg() const { return density_kg_m3 * volume_m3(); }
};

/// Reads [particles]. Every key has a default (see the .cpp for each source); the sphere size is given either
/// as `diameter_m` or as `cell_volume_m3` (volume-equivalent sphere), never both.
[[nodiscard]] ParticleParams parse_particle_params(hs::common::ConfigSection& section);

/// The defaults of parse_particle_params, for code and tests that build particles without a case file.
[[nodiscard]] ParticleParams default_particle_params();

}  // namespace hs::unresolved
