// SPDX-License-Identifier: MIT
// The AI-Feynman recovery benchmark: the whole table, three noise levels, several seeds, as `hemoscale fit` runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/case_request.hpp"

namespace hs::bench {

/// `hemoscale bench feynman [--quick] [--json FILE]`: exact recovery and fresh-point R2 on the 100 equations of
/// data/reference/feynman_ai100.csv at noise 0, 0.001 and 0.01, with `hemoscale fit`'s default search beside
/// gplearn's configuration at the same budget. With --json, every finished search is appended to FILE's
/// .runs.jsonl archive and a rerun skips what it holds (hours of work resume after any interruption); the
/// per-equation table goes to FILE's _equations.csv.
int run_feynman_bench(const hs::common::TaskOptions& options);

/// One search of a run as its archive names it: a line of FILE.runs.jsonl with this key and fingerprint is reused
/// instead of searching again.
struct FeynmanSearchId {
  std::string key;           // configuration|equation|noise|seed
  std::string fingerprint;   // of everything that decides the search's result
  std::string config;
  std::string equation_id;
  double noise = 0.0;
  std::uint64_t seed = 0;
};

/// Every search `bench feynman` (quick or full) makes, in its order: what an archive must hold for a run to compute
/// nothing (the failure-path test writes such an archive and checks the verdict on it).
std::vector<FeynmanSearchId> feynman_searches(bool quick);

}  // namespace hs::bench
