// SPDX-License-Identifier: MIT
// A campaign's (Re, r*) dataset against the acceptance rules of the resolved campaign and published ranges.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hs::campaign {

struct Range {
  double min;
  double max;
};

/// What the dataset is checked against: the grid's Re and r* values (one row each) and published ranges.
struct DatasetExpectations {
  std::vector<double> re;
  std::vector<double> r_star;
  Range gamma_plus;
  Range re_p;
};

/// The seed paper's ranges of gamma+ and Re_p, from data/reference/porcaro2026_dataset_ranges.csv (`file`).
/// Throws ConfigError when the file cannot be read or lacks one of them.
void read_published_ranges(const std::filesystem::path& file, DatasetExpectations& into);

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
  Range gamma_plus{0, 0}, re_p{0, 0}, di{0, 0}, cd{0, 0}, cl{0, 0};   // over the finite values
  int unsettled = 0;                  // rows stopped at the cap (settled or cd_settled false)
  std::vector<StokesScaling> stokes;
  [[nodiscard]] bool complete_and_valid() const { return missing.empty() && problems.empty(); }
};

/// Every row: all values finite, 0 < DI < 1, Cd > 0 (drag along the flow past the held cell), Cl < 0 (lift towards
/// the axis, the deformability-induced migration of the seed paper, sec. 3.3); every grid point present.
/// Throws ConfigError when the file cannot be read or lacks a column.
DatasetCheck check_resolved_dataset(const std::filesystem::path& csv, const DatasetExpectations& expected);

}  // namespace hs::campaign
