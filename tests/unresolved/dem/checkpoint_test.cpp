// SPDX-License-Identifier: MIT
// A run stopped at a checkpoint and resumed follows the uninterrupted run (contact springs included).
#include <gtest/gtest.h>

#include <omp.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "common/errors.hpp"
#include "dem_test_helpers.hpp"
#include "unresolved/dem/dem_checkpoint.hpp"

namespace hs::unresolved {
namespace {

DemSettings pack_settings() {
  ParticleParams p = test::rbcpack_params();
  p.max_impact_velocity_m_s = 0.1;
  return {.params = p, .domain = test::cube(3.0 * 0.99 * p.diameter_m, true), .time_step_s = 2e-7};
}

/// 6^3 spheres at spacing 0.99 d (all in contact), jittered, with random velocities.
void fill(DemSystem& dem) {
  const double a = 0.99 * dem.params().diameter_m;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 6; ++k) for (int j = 0; j < 6; ++j) for (int i = 0; i < 6; ++i) {
    dem.add_particle({(i - 2.5) * a + 0.02 * a * u(rng), (j - 2.5) * a + 0.02 * a * u(rng), (k - 2.5) * a + 0.02 * a * u(rng)},
                     {2e-2 * u(rng), 2e-2 * u(rng), 2e-2 * u(rng)});
  }
}

std::vector<double> x_by_id(const DemSystem& dem) {
  const auto& p = dem.particles();
  std::vector<double> x(p.n_owned());
  for (std::size_t i = 0; i < x.size(); ++i) x[static_cast<std::size_t>(p.id()[i])] = p.position_m()[0][i];
  return x;
}

TEST(DemCheckpoint, ResumedRunFollowsTheUninterruptedOne) {
  const auto file = std::filesystem::temp_directory_path() / "hs_dem_checkpoint_test.bin";
  DemSystem straight(pack_settings(), nullptr);
  fill(straight);
  for (int n = 0; n < 400; ++n) straight.step();

  DemSystem first(pack_settings(), nullptr);
  fill(first);
  for (int n = 0; n < 200; ++n) first.step();
  EXPECT_GT(first.contact_history().keys.size(), 100u);   // springs are saved, not only positions
  write_dem_checkpoint(first, file);
  DemSystem resumed(pack_settings(), nullptr);
  read_dem_checkpoint(resumed, file);
  for (int n = 0; n < 200; ++n) resumed.step();
  std::filesystem::remove(file);

  const auto a = x_by_id(straight), b = x_by_id(resumed);
  ASSERT_EQ(a.size(), b.size());
  // Only the summation order differs (particles re-sorted at the restart): round-off, 1e-9 of a diameter.
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9 * 7.82e-6) << "id " << i;
}

TEST(DemCheckpoint, ForeignFileIsAConfigError) {
  const auto file = std::filesystem::temp_directory_path() / "hs_dem_checkpoint_foreign.bin";
  { std::ofstream(file) << "not a checkpoint"; }
  DemSystem dem(pack_settings(), nullptr);
  EXPECT_THROW(read_dem_checkpoint(dem, file), hs::common::ConfigError);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace hs::unresolved
