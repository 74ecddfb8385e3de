// SPDX-License-Identifier: MIT
// `hemoscale bench feynman --quick` runs the AI-Feynman path end to end (table, noise, `hemoscale fit`'s search,
// recovery judge, archive), and a second invocation resumes from the archive: it computes nothing and reports the
// same rates. The full table runs for hours; this is the CI-sized part of issue #29's benchmark.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::size_t lines(const fs::path& file) {
  std::ifstream in(file);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.empty() ? 0 : 1;
  return n;
}

}  // namespace

TEST(BenchFeynman, AQuickRunArchivesEverySearchAndResumes) {
  const fs::path dir = fs::temp_directory_path() / "hs_bench_feynman_quick";
  fs::remove_all(dir);
  const fs::path json = dir / "feynman.json";
  const auto first = hs::test::run_hemoscale("bench feynman --quick --json " + json.string());
  ASSERT_EQ(first.code, 0) << first.output;   // --quick judges no target (all checks skipped)
  const nlohmann::json a = read_json(json);
  EXPECT_EQ(a.at("checks_skipped").get<int>(), 2);   // both targets listed as skipped, never met
  EXPECT_EQ(a.at("checks_failed").get<int>(), 0);
  // 10 equations (every tenth) x noise 0 and 0.01 x seed 1 x two configurations.
  EXPECT_EQ(lines(dir / "feynman.runs.jsonl"), 40u);
  EXPECT_EQ(a.at("searches_computed_this_run").get<int>(), 40);
  for (const char* key : {"exact_percent_noise0", "exact_percent_noise0.01", "exact_percent_noise0_gplearn"}) {
    EXPECT_TRUE(a.contains(key)) << key;
  }
  EXPECT_TRUE(fs::exists(dir / "feynman_equations.csv"));
  const auto second = hs::test::run_hemoscale("bench feynman --quick --json " + json.string());
  ASSERT_EQ(second.code, 0) << second.output;
  const nlohmann::json b = read_json(json);
  EXPECT_EQ(b.at("searches_computed_this_run").get<int>(), 0);
  EXPECT_EQ(b.at("rates"), a.at("rates"));
  EXPECT_EQ(lines(dir / "feynman.runs.jsonl"), 40u);
}
