// SPDX-License-Identifier: MIT
// `hemoscale study bifurcation --quick` and `study stenosis --quick`: run every case, write the table with its keys, and
// keeps finished runs on a second call (resumable); an unknown study is a ConfigError (exit 2).
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

TEST(StudyCli, BifurcationQuickWritesTheTableAndResumes) {
  const fs::path out = fs::temp_directory_path() / "hs_study_bifurcation_quick";
  fs::remove_all(out);
  const auto first = hs::test::run_hemoscale("study bifurcation --quick --output " + out.string());
  ASSERT_EQ(first.code, 0) << first.output;
  std::ifstream in(out / "bifurcation_table.json");
  const auto table = nlohmann::json::parse(in);
  for (const char* angle : {"angle_30", "angle_60", "angle_90"}) {
    ASSERT_TRUE(table.contains(angle)) << angle;
    for (const char* key : {"s_h_daughter", "s_h_outlet", "di_av", "rbc_flux_fraction_daughter", "blood_flux_fraction_daughter"}) {
      EXPECT_TRUE(table[angle][key].is_number()) << angle << " " << key;
    }
    EXPECT_TRUE(fs::exists(out / ("angle-" + std::string(angle).substr(6)) / "particles.pvd"));   // ParaView series
  }
  std::ifstream csv(out / "bifurcation_table.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 4);   // header + one row per angle
  const auto second = hs::test::run_hemoscale("study bifurcation --quick --output " + out.string());
  EXPECT_EQ(second.code, 0) << second.output;
  EXPECT_NE(second.output.find("angle-60: finished run kept"), std::string::npos) << second.output;
  const auto unknown = hs::test::run_hemoscale("study nosuch");
  EXPECT_EQ(unknown.code, 2) << unknown.output;
  fs::remove_all(out);
}

// `hemoscale study stenosis --quick`: both throats at 20 CFD steps, the table with the keys per throat, the
// plasma check (5 steps a grid), and a second call keeping the finished runs by their fingerprint.
TEST(StudyCli, StenosisQuickWritesTheTableAndResumes) {
  const fs::path out = fs::temp_directory_path() / "hs_study_stenosis_quick";
  fs::remove_all(out);
  const auto first = hs::test::run_hemoscale("study stenosis --quick --output " + out.string());
  ASSERT_EQ(first.code, 0) << first.output;
  std::ifstream in(out / "stenosis_table.json");
  const auto table = nlohmann::json::parse(in);
  for (const char* throat : {"throat_85um", "throat_55um"}) {
    ASSERT_TRUE(table.contains(throat)) << throat;
    for (const char* key : {"di_max", "x_di_max_m", "di_upstream", "di_downstream"}) {
      EXPECT_TRUE(table[throat][key].is_number()) << throat << " " << key;
    }
    EXPECT_TRUE(table[throat]["plasma_check"]["fine"]["pressure_drop_Pa"].is_number()) << throat;
  }
  EXPECT_TRUE(fs::exists(out / "throat-55um" / "particles.pvd"));   // ParaView series
  const auto second = hs::test::run_hemoscale("study stenosis --quick --output " + out.string());
  EXPECT_EQ(second.code, 0) << second.output;
  EXPECT_NE(second.output.find("throat-55um: finished run kept"), std::string::npos) << second.output;
  fs::remove_all(out);
}
