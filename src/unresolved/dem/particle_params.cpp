// SPDX-License-Identifier: MIT
// Reading [particles]: sphere size, density and the contact materials, with cited defaults.
#include "unresolved/dem/particle_params.hpp"

#include <cmath>

namespace hs::unresolved {
namespace {

// RBC density 1100 kg/m^3 (1090-1110): rbc_blood_properties.csv, "standard physiology texts".
constexpr double default_density_kg_m3 = 1100.0;
// A physical Young's modulus of an RBC-equivalent sphere does not exist (unresolved-methods.md 4.5); the
// soft artificial modulus, Poisson ratio, restitution and friction are those of the project's DEM anchor
// shared/bench/liggghts/in.rbcpack (Porcaro & Saeedipour 2024 do not state theirs: methods note section 5).
constexpr Material default_material{
    .youngs_modulus_Pa = 1.0e5, .poisson_ratio = 0.45, .restitution = 0.5, .friction = 0.3};
// Skin 10% of the diameter, as `neighbor 7.82e-7 bin` for d = 7.82e-6 m in in.rbcpack.
constexpr double default_skin_fraction_of_diameter = 0.1;
// Largest relative impact speed assumed by the Hertz-time check. Assumed: mean RBC speeds in 10-100 um
// vessels are of order 1 mm/s; in.rbcpack starts with components up to 5e-3 m/s (relative ~1.7e-2 m/s).
constexpr double default_max_impact_velocity_m_s = 2.0e-2;

Material parse_material(hs::common::ConfigSection& s, const char* prefix, const Material& fallback) {
  const std::string p(prefix);
  return {.youngs_modulus_Pa = s.positive_or(p + "youngs_modulus_Pa", fallback.youngs_modulus_Pa),
          .poisson_ratio = s.number_in_or(p + "poisson_ratio", 0.0, 0.4999, fallback.poisson_ratio),
          .restitution = s.number_in_or(p + "restitution", 1e-6, 1.0, fallback.restitution),
          .friction = s.number_in_or(p + "friction", 0.0, 10.0, fallback.friction)};
}

}  // namespace

double volume_equivalent_diameter(double volume_m3) {
  return std::cbrt(6.0 * volume_m3 / std::numbers::pi);
}

ParticleParams default_particle_params() {
  const double d_m = volume_equivalent_diameter(rbc_volume_m3);
  return {.diameter_m = d_m,
          .density_kg_m3 = default_density_kg_m3,
          .particle = default_material,
          .wall = default_material,
          .skin_m = default_skin_fraction_of_diameter * d_m,
          .max_impact_velocity_m_s = default_max_impact_velocity_m_s,
          .limit_normal_force = false};   // LIGGGHTS default (limitForce off)
}

ParticleParams parse_particle_params(hs::common::ConfigSection& s) {
  ParticleParams p = default_particle_params();
  s.forbid_together("diameter_m", "cell_volume_m3", "the sphere size is given once: as a diameter or as a volume");
  if (s.has("diameter_m")) {
    p.diameter_m = s.positive("diameter_m");
  } else {
    p.diameter_m = volume_equivalent_diameter(s.positive_or("cell_volume_m3", rbc_volume_m3));
    s.derived("diameter_m", p.diameter_m);
  }
  p.density_kg_m3 = s.positive_or("density_kg_m3", default_density_kg_m3);
  p.particle = parse_material(s, "", default_material);
  p.wall = parse_material(s, "wall_", p.particle);
  p.skin_m = s.positive_or("skin_m", default_skin_fraction_of_diameter * p.diameter_m);
  p.max_impact_velocity_m_s = s.positive_or("max_impact_velocity_m_s", default_max_impact_velocity_m_s);
  p.limit_normal_force = s.boolean_or("limit_normal_force", false);
  return p;
}

}  // namespace hs::unresolved
