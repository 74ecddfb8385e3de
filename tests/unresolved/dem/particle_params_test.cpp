// SPDX-License-Identifier: MIT
// The [particles] case section: defaults, the volume-equivalent diameter, strictness.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {
namespace {

TEST(ParticleParams, DefaultIsTheVolumeEquivalentRbcSphere) {
  const ParticleParams p = default_particle_params();
  // (6 * 94.1 um^3 / pi)^(1/3) = 5.644 um (validation/README.md: ~5.64 um).
  EXPECT_NEAR(p.diameter_m, 5.644e-6, 1e-9);
  EXPECT_NEAR(p.volume_m3(), 94.1e-18, 1e-22);
  EXPECT_DOUBLE_EQ(p.density_kg_m3, 1100.0);
}

TEST(ParticleParams, ParsesSiKeysAndRecordsTheDerivedDiameter) {
  auto cfg = hs::common::ConfigFile::parse(
      "[particles]\ncell_volume_m3 = 90e-18\nyoungs_modulus_Pa = 2e5\nwall_friction = 0.1\n", "case.toml");
  auto s = cfg->root().section("particles");
  const ParticleParams p = parse_particle_params(s);
  cfg->finish();
  EXPECT_NEAR(p.diameter_m, volume_equivalent_diameter(90e-18), 1e-15);
  EXPECT_DOUBLE_EQ(p.particle.youngs_modulus_Pa, 2e5);
  EXPECT_DOUBLE_EQ(p.wall.youngs_modulus_Pa, 2e5);   // wall defaults to the particle material
  EXPECT_DOUBLE_EQ(p.wall.friction, 0.1);
}

TEST(ParticleParams, DiameterAndVolumeTogetherIsAnError) {
  auto cfg = hs::common::ConfigFile::parse("[particles]\ncell_volume_m3 = 90e-18\ndiameter_m = 5e-6\n", "case.toml");
  auto s = cfg->root().section("particles");
  EXPECT_THROW((void)parse_particle_params(s), hs::common::ConfigError);
}

TEST(ParticleParams, RestitutionOutOfRangeIsAnError) {
  auto cfg = hs::common::ConfigFile::parse("[particles]\nrestitution = 1.5\n", "case.toml");
  auto s = cfg->root().section("particles");
  EXPECT_THROW((void)parse_particle_params(s), hs::common::ConfigError);
}

}  // namespace
}  // namespace hs::unresolved
