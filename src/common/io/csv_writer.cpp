// SPDX-License-Identifier: MIT
// CSV tables with unit-suffixed column names.
#include "common/io/csv_writer.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::common {

CsvWriter::CsvWriter(const std::filesystem::path& file, std::vector<std::string> columns, bool append)
    : columns_(std::move(columns)) {
  const bool write_header = !append || !std::filesystem::exists(file) || std::filesystem::file_size(file) == 0;
  out_.open(file, append ? std::ios::app : std::ios::trunc);
  if (!out_) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
  if (write_header) {
    for (std::size_t i = 0; i < columns_.size(); ++i) out_ << (i ? "," : "") << columns_[i];
    out_ << '\n';
    out_.flush();
  }
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) {
    throw std::logic_error(fmt::format("CsvWriter: {} values for {} columns", values.size(), columns_.size()));
  }
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) line += fmt::format("{}{:.10g}", i ? "," : "", values[i]);
  out_ << line << '\n';
  out_.flush();
}

int CsvTable::column_index(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const int c = column_index(name);
  if (c < 0) throw std::out_of_range("no column " + name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[static_cast<std::size_t>(c)]);
  return out;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
    cells.push_back(cell);
  }
  return cells;
}

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ConfigError(fmt::format("{}: cannot read CSV file", file.string()));
  CsvTable t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (t.columns.empty()) {
      t.columns = split_csv_line(line);
      continue;
    }
    std::vector<double> row;
    for (const auto& cell : split_csv_line(line)) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      row.push_back(end != cell.c_str() && *end == '\0' ? v : std::numeric_limits<double>::quiet_NaN());
    }
    row.resize(t.columns.size(), std::numeric_limits<double>::quiet_NaN());
    t.rows.push_back(std::move(row));
  }
  if (t.columns.empty()) throw ConfigError(fmt::format("{}: CSV file has no header line", file.string()));
  return t;
}

}  // namespace hs::common
