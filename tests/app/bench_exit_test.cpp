// SPDX-License-Identifier: MIT
// `hemoscale bench NAME` exits 1 when a measured value misses its documented target and 0 when it meets it, shown
// end to end on the one bench whose --quick run measures its target's own case on any machine: lbm (the 128^3 box,
// in-place AA kernel, 2 threads, vs the triad roofline). The target is moved with --tighten (a test-only option)
// to where the outcome does not depend on the machine: a kernel does not run 8x faster than its memory traffic allows,
// so a target of 0.82 x 10 = 8.2 must fail; 0.82 x 0.01 = 0.0082 is 35x under the 0.28 measured on this 2-core machine
// with three builds running beside it (2026-12-02), so it must pass.
#include <gtest/gtest.h>

#include "support/run_command.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

hs::test::CommandResult run(const std::string& args) { return hs::test::run_hemoscale(args); }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST(BenchExit, AMissedTargetIsExitOneAndNamedInTheJson) {
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_missed";
  fs::remove_all(dir);
  const auto r = run("bench lbm --quick --tighten 10 --json " + (dir / "lbm.json").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED  roofline_fraction"), std::string::npos) << r.output;
  const nlohmann::json j = read_json(dir / "lbm.json");
  EXPECT_FALSE(j.at("passed").get<bool>());
  EXPECT_EQ(j.at("checks_failed").get<int>(), 1);
}

TEST(BenchExit, AMetTargetIsExitZero) {
  const fs::path dir = fs::temp_directory_path() / "hs_bench_exit_met";
  fs::remove_all(dir);
  const auto r = run("bench lbm --quick --tighten 0.01 --json " + (dir / "lbm.json").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(read_json(dir / "lbm.json").at("passed").get<bool>());
}
