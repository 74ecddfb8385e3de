// SPDX-License-Identifier: MIT
// The one layout of summary.json (schema 1), shared by every case of `hemoscale run` (docs/outputs.md, "summary.json"):
// the case gives its blocks (results, groups, numerics, timings) and its checks; assemble_summary adds the common ones;
// summary_schema_problems says how a summary departs from the layout (the writer refuses one that does, and a test runs
// every case folder against it).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/check_list.hpp"

namespace hs::common {

/// Raised with every change of the layout; readers of older archived summaries (no schema_version) may need fallbacks.
inline constexpr int kSummarySchemaVersion = 1;

/// What a run adds besides the case's blocks.
struct SummaryRun {
  std::string case_type;
  bool quick = false;
  int mpi_ranks = 1;
  double wall_time_s = 0.0;
  double peak_memory_GiB = 0.0;   // the job's: each rank's peak resident set size, summed
  nlohmann::json provenance;   // common::provenance()
};

/// The summary.json of a run: `blocks` may hold only results, groups, numerics and timings (a missing one is written
/// empty); the checks give `checks`, `passed`, `checks_failed`, `checks_skipped`. Throws std::logic_error (a bug in the
/// case) when the result departs from the schema.
nlohmann::json assemble_summary(nlohmann::json blocks, const CheckList& checks, const SummaryRun& run);

/// Every way `summary` departs from schema 1, one sentence each naming the key; empty when it conforms.
std::vector<std::string> summary_schema_problems(const nlohmann::json& summary);

}  // namespace hs::common
