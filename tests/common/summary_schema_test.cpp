// SPDX-License-Identifier: MIT
// summary.json's one layout: what assemble_summary writes conforms, and each kind of departure is named.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "common/run_folder.hpp"
#include "common/summary_schema.hpp"

using namespace hs::common;

namespace {

SummaryRun run_of(const std::string& type, bool quick) {
  return {.case_type = type, .quick = quick, .mpi_ranks = 1, .wall_time_s = 2.0, .peak_memory_GiB = 0.25,
          .provenance = provenance()};
}

nlohmann::json good() {
  CheckList checks;
  checks.expect("u_max vs Poiseuille", true, "0.12 %");
  checks.skip("settled", "--quick");
  return assemble_summary({{"results", {{"u_max_m_s", 1e-3}}}, {"groups", {{"reynolds", 0.5}}},
                           {"timings", {{"collide", {{"seconds", 1.0}, {"calls", 3}, {"share", 1.0}}}}}},
                          checks, run_of("test", true));
}

bool names(const std::vector<std::string>& problems, const std::string& key) {
  for (const auto& p : problems) {
    if (p.find(key) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

TEST(SummarySchema, AssembledSummaryConformsAndHasEveryBlock) {
  const auto s = good();
  EXPECT_TRUE(summary_schema_problems(s).empty());
  EXPECT_EQ(s["schema_version"], kSummarySchemaVersion);
  EXPECT_TRUE(s["numerics"].is_object());   // not given: written empty
  EXPECT_TRUE(s["passed"].get<bool>());
  EXPECT_EQ(s["checks_skipped"], 1);
  EXPECT_EQ(s["quick"], true);
  EXPECT_EQ(s["peak_memory_GiB"], 0.25);
}

TEST(SummarySchema, PeakMemoryIsOptionalButANumber) {
  auto s = good();
  s.erase("peak_memory_GiB");   // summaries archived before the key was added
  EXPECT_TRUE(summary_schema_problems(s).empty());
  s["peak_memory_GiB"] = "1 GiB";
  EXPECT_TRUE(names(summary_schema_problems(s), "`peak_memory_GiB` is string"));
}

TEST(SummarySchema, EachDepartureIsNamed) {
  auto s = good();
  s["check_passed"] = true;   // the old tube-poiseuille key
  EXPECT_TRUE(names(summary_schema_problems(s), "`check_passed` is no key"));
  s = good();
  s.erase("timings");
  EXPECT_TRUE(names(summary_schema_problems(s), "`timings` is missing"));
  s = good();
  s["groups"]["flow_mode"] = "tumbling";   // a group is a number
  EXPECT_TRUE(names(summary_schema_problems(s), "group `flow_mode`"));
  s = good();
  s["checks"][0]["status"] = "failed";   // `passed` must follow the checks
  EXPECT_TRUE(names(summary_schema_problems(s), "`passed`"));
  s = good();
  s["provenance"].erase("git_commit");
  EXPECT_TRUE(names(summary_schema_problems(s), "provenance.git_commit"));
  s = good();
  s.erase("schema_version");   // a summary archived before schema 1
  EXPECT_TRUE(names(summary_schema_problems(s), "schema_version"));
}

TEST(SummarySchema, TheWriterRefusesAStrayBlock) {
  EXPECT_THROW((void)assemble_summary({{"stage_timings", nlohmann::json::object()}}, {}, run_of("test", false)),
               std::logic_error);
}
