// SPDX-License-Identifier: MIT
// A benchmark's documented targets as checks: `hemoscale bench NAME` exits 1 when a measured value misses one. A
// target comes from the issue that set it (named in `source`); --tighten F multiplies a floor and divides a ceiling
// by F, for tests of the failure path. A value that could not be measured (a peer code not installed, a size left
// out by --quick) is a skipped check, never a met target.
#pragma once

#include <optional>
#include <string>

#include <fmt/format.h>

#include "common/case_request.hpp"
#include "common/check_list.hpp"

namespace hs::bench {

/// value >= target * tighten.
inline void expect_at_least(hs::common::CheckList& checks, const hs::common::TaskOptions& options, const std::string& name,
                            std::optional<double> value, double target, const std::string& source) {
  const double floor = target * options.tighten;
  if (!value) {
    checks.skip(name, fmt::format("not measured in this run (target >= {:.3g}, {})", floor, source));
    return;
  }
  checks.expect(name, *value >= floor, fmt::format("{:.3g} (target >= {:.3g}, {})", *value, floor, source));
}

/// value <= target / tighten.
inline void expect_at_most(hs::common::CheckList& checks, const hs::common::TaskOptions& options, const std::string& name,
                           std::optional<double> value, double target, const std::string& source) {
  const double ceiling = target / options.tighten;
  if (!value) {
    checks.skip(name, fmt::format("not measured in this run (target <= {:.3g}, {})", ceiling, source));
    return;
  }
  checks.expect(name, *value <= ceiling, fmt::format("{:.3g} (target <= {:.3g}, {})", *value, ceiling, source));
}

}  // namespace hs::bench
