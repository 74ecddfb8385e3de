// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/memory_budget.hpp"

namespace {

using hs::common::SizingKey;

TEST(MemoryBudget, AvailableMemoryIsPositiveAndBelowPhysical) {
  const double available = hs::common::available_memory_bytes();
  EXPECT_GT(available, 0.0);
  EXPECT_LT(available, 1e15);   // no machine this runs on has a petabyte: the reading is not garbage
}

TEST(MemoryBudget, FitsIsSilentTooLargeNamesEstimateKeysAndHint) {
  const auto file = hs::common::ConfigFile::parse("", "case.toml");
  const std::array<SizingKey, 2> keys{{{"[geometry] radius_m", 25.0, true}, {"[numerics] dx_m", 1e-6, true}}};
  const double gib = 1024.0 * 1024.0 * 1024.0;
  EXPECT_NO_THROW(hs::common::require_memory(*file, {"a lattice", 1.0 * gib}, keys, 2.0 * gib));
  try {
    hs::common::require_memory(*file, {"a lattice of 3 x 3 x 3 nodes", 3.0 * gib}, keys, 2.0 * gib);
    FAIL() << "3 GiB needed, 2 available: not refused";
  } catch (const hs::common::ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("case.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("~3 GiB for a lattice of 3 x 3 x 3 nodes"), std::string::npos) << m;
    EXPECT_NE(m.find("2 GiB available"), std::string::npos) << m;
    EXPECT_NE(m.find("[geometry] radius_m = 25, [numerics] dx_m = 1e-06"), std::string::npos) << m;
    EXPECT_NE(m.find("25 micrometres is written 25e-6"), std::string::npos) << m;
    EXPECT_EQ(m.find("1e-06 micrometres"), std::string::npos) << "a micrometre-scale spacing got the hint: " << m;
  }
}

TEST(MemoryBudget, MicrometreHintOnlyFromOneMillimetre) {
  EXPECT_EQ(hs::common::micrometre_hint(500e-6), "");   // a 500 um device: cell scale
  EXPECT_NE(hs::common::micrometre_hint(2.5e-3).find("2.5 mm"), std::string::npos);
  EXPECT_NE(hs::common::micrometre_hint(8.0).find("8e-6"), std::string::npos);
}

}  // namespace
