// SPDX-License-Identifier: MIT
#include "common/check_list.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "common/log.hpp"

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

std::vector<std::string> CheckList::lines(const std::string& what) const {
  std::vector<std::string> out;
  for (const Check& c : checks_) {
    if (c.status == CheckStatus::passed) continue;
    out.push_back(fmt::format("  {} {}: {}", c.status == CheckStatus::failed ? "FAILED " : "skipped", c.name, c.detail));
  }
  const int n_failed = failed();
  const int n_skipped = skipped();
  const int n_passed = static_cast<int>(checks_.size()) - n_failed - n_skipped;
  out.push_back(fmt::format("{}: {} of {} checks passed, {} failed, {} skipped", what, n_passed, checks_.size(), n_failed,
                            n_skipped));
  return out;
}

void CheckList::print(const std::string& what) const {
  for (const std::string& line : lines(what)) fmt::print("{}\n", line);
  std::fflush(stdout);
}

void CheckList::print(Log& log, const std::string& what) const {
  for (const std::string& line : lines(what)) log.result("{}", line);
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
