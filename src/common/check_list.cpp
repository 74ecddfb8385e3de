// SPDX-License-Identifier: MIT
#include "common/check_list.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

namespace hs::common {

const char* check_status_name(CheckStatus s) {
  switch (s) {
    case CheckStatus::passed: return "passed";
    case CheckStatus::failed: return "failed";
    case CheckStatus::skipped: return "skipped";
  }
  return "?";
}

void CheckList::expect(std::string name, bool passed, std::string detail) {
  checks_.push_back({std::move(name), passed ? CheckStatus::passed : CheckStatus::failed, std::move(detail)});
}

void CheckList::skip(std::string name, std::string reason) {
  checks_.push_back({std::move(name), CheckStatus::skipped, std::move(reason)});
}

int CheckList::failed() const {
  return static_cast<int>(std::count_if(checks_.begin(), checks_.end(), [](const Check& c) { return c.status == CheckStatus::failed; }));
}

int CheckList::skipped() const {
  return static_cast<int>(std::count_if(checks_.begin(), checks_.end(), [](const Check& c) { return c.status == CheckStatus::skipped; }));
}

void CheckList::print(const std::string& what) const {
  for (const Check& c : checks_) {
    if (c.status == CheckStatus::passed) continue;
    fmt::print("  {} {}: {}\n", c.status == CheckStatus::failed ? "FAILED " : "skipped", c.name, c.detail);
  }
  const int n_failed = failed();
  const int n_skipped = skipped();
  const int n_passed = static_cast<int>(checks_.size()) - n_failed - n_skipped;
  fmt::print("{}: {} of {} checks passed, {} failed, {} skipped\n", what, n_passed, checks_.size(), n_failed, n_skipped);
  std::fflush(stdout);
}

void CheckList::write_to(nlohmann::json& result) const {
  nlohmann::json list = nlohmann::json::array();
  for (const Check& c : checks_) list.push_back({{"name", c.name}, {"status", check_status_name(c.status)}, {"detail", c.detail}});
  result["checks"] = list;
  result["checks_failed"] = failed();
  result["checks_skipped"] = skipped();
  result["passed"] = failed() == 0;
}

}  // namespace hs::common
