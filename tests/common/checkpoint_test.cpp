// SPDX-License-Identifier: MIT
// Checkpoints read back bit-exactly; a truncated file is refused, never half-loaded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "common/errors.hpp"
#include "common/io/checkpoint.hpp"

namespace fs = std::filesystem;
using hs::common::Checkpoint;

TEST(Checkpoint, RoundTripsArraysAndMeta) {
  const auto dir = fs::temp_directory_path() / "hs_checkpoint_test";
  fs::remove_all(dir);
  Checkpoint c;
  const std::vector<double> f{1.0 / 3.0, -2.5e-300, 7.0};
  const std::vector<std::int64_t> ids{4, -9};
  c.put("populations", f);
  c.put("ids", ids);
  c.meta()["step"] = 1234;
  c.write(dir, 1);
  ASSERT_TRUE(Checkpoint::exists(dir, 1));
  const auto back = Checkpoint::read(dir, 1);
  EXPECT_EQ(back.doubles("populations"), f);
  EXPECT_EQ(back.integers("ids"), ids);
  EXPECT_EQ(back.meta()["step"], 1234);
}

TEST(Checkpoint, TruncatedFileIsRefused) {
  const auto dir = fs::temp_directory_path() / "hs_checkpoint_truncated";
  fs::remove_all(dir);
  Checkpoint c;
  c.put("x", std::vector<double>(100, 1.0));
  c.write(dir);
  fs::resize_file(Checkpoint::file_for(dir, 0), fs::file_size(Checkpoint::file_for(dir, 0)) - 20);
  EXPECT_THROW(Checkpoint::read(dir), hs::common::ConfigError);
  EXPECT_THROW(Checkpoint::read(fs::temp_directory_path() / "hs_no_such_checkpoint"), hs::common::ConfigError);
}
