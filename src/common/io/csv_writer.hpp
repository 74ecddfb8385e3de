// SPDX-License-Identifier: MIT
// CSV tables with unit-suffixed column names (timeseries.csv, datasets, validation tables).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hs::common {

class CsvWriter {
 public:
  /// Creates (or, with `append`, continues) a table. Column names carry their unit: "time_s", "drag_N".
  CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns, bool append = false);
  /// One row of numbers, one per column (checked); written with 10 significant digits and flushed.
  void row(const std::vector<double>& values);
  [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::vector<std::string> columns_;
  std::ofstream out_;
};

/// A whole CSV file read into columns by name (numbers only; non-numeric cells become NaN).
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] int column_index(const std::string& name) const;   // -1 when absent
  [[nodiscard]] std::vector<double> column(const std::string& name) const;
};
/// The comma-separated cells of one line, spaces and a trailing '\r' trimmed (no quoting: the project's CSVs have none).
std::vector<std::string> split_csv_line(const std::string& line);
/// Reads a CSV with a header line; lines starting with '#' are comments. Throws ConfigError on an unreadable file.
CsvTable read_csv(const std::filesystem::path& file);

}  // namespace hs::common
