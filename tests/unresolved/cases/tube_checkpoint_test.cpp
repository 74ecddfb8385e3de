// SPDX-License-Identifier: MIT
// `validate pries` keeps each running tube's checkpoint beside its archived summary (issue #25: a D = 100 um tube
// runs for hours, the table is a resumable campaign): an interrupted tube resumes from it when its fingerprint is
// the same, and a checkpoint written under another fingerprint is discarded, never continued.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/config/config_file.hpp"
#include "common/io/checkpoint.hpp"
#include "unresolved/cases/short_tube_case.hpp"
#include "unresolved/cases/tube_pries.hpp"
#include "validate/tube_checkpoint.hpp"

namespace {

namespace fs = std::filesystem;
using hs::unresolved::tube_checkpoint;

fs::path fresh_archive(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir / "D30_ht0.10_seed1.json";
}

/// The small rigid-sphere tube at Ht_c 0.05, run for `steps` CFD steps of 0.2 ms.
hs::unresolved::TubePriesConfig small_tube(int steps) {
  const std::string text = hs::test::short_tube_case("0.05", "drag = \"stokes\"\n", "125", std::to_string(2e-4 * steps));
  auto file = hs::common::ConfigFile::parse(text, "case.toml");
  (void)file->root().section("case").string("type");
  return hs::unresolved::parse_tube_pries(*file, false);
}

TEST(TubeCheckpoint, AFreshTubeStartsFromRestInItsOwnFolder) {
  const fs::path archive = fresh_archive("hs_tube_checkpoint_fresh");
  const auto restart = tube_checkpoint(archive, "model A");
  EXPECT_FALSE(restart.resume);
  EXPECT_EQ(restart.dir, archive.parent_path() / "D30_ht0.10_seed1.checkpoint");
  EXPECT_TRUE(fs::is_directory(restart.dir));
}

TEST(TubeCheckpoint, AFolderWithoutACheckpointStartsFromRest) {
  // Killed before its first checkpoint: only the fingerprint is there.
  const fs::path archive = fresh_archive("hs_tube_checkpoint_empty");
  (void)tube_checkpoint(archive, "model A");
  EXPECT_FALSE(tube_checkpoint(archive, "model A").resume);
}

TEST(TubeCheckpoint, AnotherFingerprintsCheckpointIsDiscarded) {
  const fs::path archive = fresh_archive("hs_tube_checkpoint_other");
  const auto first = tube_checkpoint(archive, "model A");
  hs::common::Checkpoint cp;
  cp.meta()["step"] = 7;
  cp.write(first.dir);
  EXPECT_TRUE(tube_checkpoint(archive, "model A").resume);   // the same tube: continued
  const auto other = tube_checkpoint(archive, "model B");
  EXPECT_FALSE(other.resume);
  EXPECT_FALSE(hs::common::Checkpoint::exists(other.dir));
  EXPECT_FALSE(tube_checkpoint(archive, "model A").resume);   // A's checkpoint is gone for good
  hs::unresolved::discard_tube_checkpoint(archive);
  EXPECT_FALSE(fs::exists(other.dir));
}

TEST(TubeCheckpoint, AnInterruptedTubeResumesToTheSameResult) {
  // A tube stopped after 20 steps and resumed to 40 gives the uninterrupted 40-step tube's Ht_d and mu_rel: the
  // series before the checkpoint is carried, so the averages are the same to round-off.
  const fs::path archive = fresh_archive("hs_tube_checkpoint_resume");
  const auto noop = [](const hs::unresolved::TubePriesSample&) {};
  (void)hs::unresolved::simulate_tube_pries(small_tube(20), noop, tube_checkpoint(archive, "small tube"));
  const auto restart = tube_checkpoint(archive, "small tube");
  ASSERT_TRUE(restart.resume);
  const auto resumed = hs::unresolved::simulate_tube_pries(small_tube(40), noop, restart);
  const auto whole = hs::unresolved::simulate_tube_pries(small_tube(40), noop);
  EXPECT_NEAR(resumed.ht_d, whole.ht_d, 1e-12 * whole.ht_d);
  EXPECT_NEAR(resumed.mu_rel, whole.mu_rel, 1e-12 * whole.mu_rel);
  hs::unresolved::discard_tube_checkpoint(archive);
}

}  // namespace
