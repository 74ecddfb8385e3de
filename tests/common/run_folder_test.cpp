// SPDX-License-Identifier: MIT
// Run folders are never overwritten.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "common/run_folder.hpp"

namespace fs = std::filesystem;

TEST(RunFolder, NewFoldersNeverCollide) {
  const auto parent = fs::temp_directory_path() / "hs_run_folder_test";
  fs::remove_all(parent);
  const auto a = hs::common::RunFolder::create_new(parent);
  const auto b = hs::common::RunFolder::create_new(parent);
  EXPECT_NE(a.path(), b.path());
  EXPECT_TRUE(fs::is_directory(a.vtk_dir()));
  EXPECT_TRUE(fs::is_directory(b.checkpoint_dir()));
}

TEST(RunFolder, ExactFolderMustBeEmpty) {
  const auto dir = fs::temp_directory_path() / "hs_run_folder_exact";
  fs::remove_all(dir);
  auto f = hs::common::RunFolder::create_exact(dir);
  std::ofstream(f.file("summary.json")) << "{}";
  EXPECT_THROW(hs::common::RunFolder::create_exact(dir), hs::common::ConfigError);
  EXPECT_NO_THROW(hs::common::RunFolder::open_existing(dir));
}

TEST(Provenance, NamesVersionAndCommit) {
  const auto p = hs::common::provenance();
  EXPECT_TRUE(p.contains("version"));
  EXPECT_TRUE(p.contains("git_commit"));
}
