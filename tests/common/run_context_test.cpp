// SPDX-License-Identifier: MIT
// The shared run start: unknown keys stop it before any folder is made; a run writes its resolved case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/run_context.hpp"

namespace fs = std::filesystem;
using namespace hs::common;

TEST(RunContext, CreatesFolderAndResolvedCase) {
  const auto dir = fs::temp_directory_path() / "hs_run_context";
  fs::remove_all(dir);
  auto config = ConfigFile::parse("[fluid]\ndensity_kg_m3 = 1025\n", (dir / "case.toml").string());
  (void)config->root().section("fluid").positive("density_kg_m3");
  const CaseRequest request{.case_dir = dir, .config = config.get(), .output_dir = std::nullopt};
  auto ctx = RunContext::start(request, "test");
  EXPECT_TRUE(fs::exists(ctx.folder().file("case.resolved.toml")));
  EXPECT_TRUE(fs::exists(ctx.folder().file("log.txt")));
  ctx.write_summary({{"results", {{"answer", 42}}}});
  EXPECT_TRUE(fs::exists(ctx.folder().file("summary.json")));
  EXPECT_EQ(ctx.folder().path().parent_path(), dir / "runs");
}

TEST(RunContext, UnknownKeyStopsBeforeAnyFolderIsMade) {
  const auto dir = fs::temp_directory_path() / "hs_run_context_bad";
  fs::remove_all(dir);
  auto config = ConfigFile::parse("[fluid]\ndensity_kg_m3 = 1025\nviscosity = 1\n", (dir / "case.toml").string());
  (void)config->root().section("fluid").positive("density_kg_m3");
  const CaseRequest request{.case_dir = dir, .config = config.get(), .output_dir = std::nullopt};
  EXPECT_THROW(RunContext::start(request, "test"), ConfigError);
  EXPECT_FALSE(fs::exists(dir / "runs"));
}

TEST(RunContext, QuickIsRecordedInResolvedCaseSummaryAndLog) {
  const auto dir = fs::temp_directory_path() / "hs_run_context_quick";
  fs::remove_all(dir);
  auto config = ConfigFile::parse("[fluid]\ndensity_kg_m3 = 1025\n", (dir / "case.toml").string());
  (void)config->root().section("fluid").positive("density_kg_m3");
  const CaseRequest request{.case_dir = dir, .config = config.get(), .output_dir = std::nullopt, .quiet = true,
                            .quick = true};
  auto ctx = RunContext::start(request, "test");
  ctx.log().info("result 42");
  ctx.write_summary({{"results", {{"answer", 42}}}});
  auto read = [&](const char* name) {
    std::ostringstream text;
    text << std::ifstream(ctx.folder().file(name)).rdbuf();
    return text.str();
  };
  EXPECT_NE(read("case.resolved.toml").find("[invocation]\nquick = true"), std::string::npos) << read("case.resolved.toml");
  EXPECT_EQ(nlohmann::json::parse(read("summary.json"))["quick"], true);
  EXPECT_NE(read("log.txt").find("[--quick] info: result 42"), std::string::npos) << read("log.txt");
  fs::remove_all(dir);
}
