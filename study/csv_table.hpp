// SPDX-License-Identifier: MIT
// A numeric CSV table as the runs write them (timeseries.csv: one header line, then numbers).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hs::study {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

/// Reads `file`; ConfigError naming the file and line for a missing file, a row of another width or a field that is
/// not a number.
[[nodiscard]] CsvTable read_csv_table(const std::filesystem::path& file);

}  // namespace hs::study
