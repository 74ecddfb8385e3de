// SPDX-License-Identifier: MIT
// The resolved dataset against the campaign's acceptance rules and the seed paper's ranges.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hs::campaign {

/// The seed paper's grid (section 4): channel Re x r*, one dataset row each.
inline const std::vector<double> kPaperRe{0.1, 0.2, 0.3, 0.4, 0.5};
inline const std::vector<double> kPaperRStar{0.2, 0.3, 0.4, 0.5, 0.6, 0.7};

/// Ranges the seed paper reports for its dataset (section 4, "applicability limits").
struct Range {
  double min;
  double max;
};
inline constexpr Range kPaperGammaPlus{0.02, 0.35};
inline constexpr Range kPaperReP{0.01, 0.12};

struct RowProblem {
  double re;
  double r_star;
  std::string what;
};

/// Cd Re_p (Stokes drag: independent of Re_p at Re_p << 1) at one r*, over its rows.
struct StokesScaling {
  double r_star;
  int rows;
  double median;
  double max_deviation;   // max |Cd Re_p / median - 1|
};

struct DatasetCheck {
  int rows = 0;
  int rows_expected = 0;
  std::vector<std::string> missing;   // "Re 0.3, r* 0.2"
  std::vector<RowProblem> problems;   // a rule a present row breaks
  Range gamma_plus{0, 0}, re_p{0, 0}, di{0, 0}, cd{0, 0}, cl{0, 0};
  int unsettled = 0;                  // rows stopped at the cap (settled or cd_settled false)
  std::vector<StokesScaling> stokes;
  [[nodiscard]] bool complete_and_valid() const { return missing.empty() && problems.empty(); }
};

/// Every row: all values finite, 0 < DI < 1, Cd > 0 (drag along the flow past the held cell), Cl < 0 (lift towards
/// the axis, the deformability-induced migration of the seed paper, sec. 3.3); every grid point present.
/// Throws ConfigError when the file cannot be read or lacks a column.
DatasetCheck check_resolved_dataset(const std::filesystem::path& csv);

}  // namespace hs::campaign
