// SPDX-License-Identifier: MIT
// Particle storage: sorting keeps every column together, ghosts mirror and fold back, VTK output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "unresolved/dem/particle_output.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {
namespace {

ParticleStore three_particles() {
  ParticleStore s;
  for (int k = 0; k < 3; ++k) {
    s.add({.position_m = {1.0 * k, 0, 0}, .velocity_m_s = {0, 1.0 * k, 0}, .angular_velocity_rad_s = {},
           .radius_m = 0.1 * (k + 1), .mass_kg = 1.0 + k, .id = 10 + k});
  }
  return s;
}

TEST(ParticleStore, PermuteMovesAllColumnsTogether) {
  ParticleStore s = three_particles();
  s.deformation_index()[1] = 0.3;
  s.drag_coefficient_N_s_m()[1] = 2.0;
  s.permute_owned({2, 1, 0});
  EXPECT_EQ(s.id()[0], 12);
  EXPECT_DOUBLE_EQ(s.position_m()[0][0], 2.0);
  EXPECT_DOUBLE_EQ(s.velocity_m_s()[1][0], 2.0);
  EXPECT_DOUBLE_EQ(s.radius_m()[0], 0.3);
  EXPECT_DOUBLE_EQ(s.deformation_index()[1], 0.3);
  EXPECT_DOUBLE_EQ(s.drag_coefficient_N_s_m()[1], 2.0);
}

TEST(ParticleStore, GhostsMirrorOwnersAndFoldForcesBack) {
  ParticleStore s = three_particles();
  const std::size_t g = s.add_ghost(1, {5.0, 0, 0});
  EXPECT_EQ(s.n_ghost(), 1u);
  EXPECT_EQ(s.id()[g], 11);
  EXPECT_DOUBLE_EQ(s.position_m()[0][g], 6.0);
  s.position_m()[0][1] = 1.5;
  s.update_ghosts();
  EXPECT_DOUBLE_EQ(s.position_m()[0][g], 6.5);
  s.force_N()[2][g] = 4.0;
  s.force_N()[2][1] = 1.0;
  s.fold_ghost_forces();
  EXPECT_DOUBLE_EQ(s.force_N()[2][1], 5.0);
  EXPECT_DOUBLE_EQ(s.force_N()[2][g], 0.0);
}

TEST(ParticleStore, WritesVtp) {
  const ParticleStore s = three_particles();
  const auto file = std::filesystem::temp_directory_path() / "hs_dem_particles_test.vtp";
  write_particles_vtp(s, file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(text.str().find("deformation_index"), std::string::npos);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace hs::unresolved
