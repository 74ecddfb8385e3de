// SPDX-License-Identifier: MIT
// The verdict of a validation or benchmark: named checks that passed, failed or were skipped (with the reason), one
// exit code from them. A validation that cannot reach the state its band needs (a --quick run, say) skips that check
// and says so; it never counts a skipped check as agreement.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hs::common {

class Log;

enum class CheckStatus { passed, failed, skipped };

struct Check {
  std::string name;     // what is checked, e.g. "D = 30 um, Ht_c 0.05: Ht_d vs Pries"
  CheckStatus status;
  std::string detail;   // the measured value against its band, or why the check was skipped
};

class CheckList {
 public:
  /// Records a check with its outcome; `detail` says value and band ("+15.6% vs +-5%").
  void expect(std::string name, bool passed, std::string detail);
  /// Records a check that this run cannot decide, and why.
  void skip(std::string name, std::string reason);

  [[nodiscard]] const std::vector<Check>& checks() const { return checks_; }
  [[nodiscard]] int failed() const;
  [[nodiscard]] int skipped() const;
  /// 0 when no check failed (skipped ones are listed, not counted as passed), 1 otherwise.
  [[nodiscard]] int exit_code() const { return failed() == 0 ? 0 : 1; }

  /// One line per failed and skipped check, then "<what>: N of M checks passed, N failed, N skipped" (stdout).
  void print(const std::string& what) const;
  /// The same lines as result lines of a run's log: stdout with the log's prefix ("[--quick] "), and log.txt.
  void print(Log& log, const std::string& what) const;
  /// {"checks": [{name, status, detail}], "passed": bool, "checks_failed": N, "checks_skipped": N}
  void write_to(nlohmann::json& result) const;

 private:
  [[nodiscard]] std::vector<std::string> lines(const std::string& what) const;
  std::vector<Check> checks_;
};

/// The name a status prints and is written with: "passed", "failed", "skipped".
const char* check_status_name(CheckStatus s);

}  // namespace hs::common
