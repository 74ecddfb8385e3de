// SPDX-License-Identifier: MIT
#include "validate/text_table.hpp"

#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"

namespace hs::validate {

std::vector<TextRow> read_text_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw common::ConfigError(fmt::format("{}: cannot read it", file.string()));
  std::vector<TextRow> rows;
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \r") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> cells = common::split_csv_line(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    TextRow row;
    for (std::size_t c = 0; c < header.size() && c < cells.size(); ++c) row[header[c]] = cells[c];
    rows.push_back(std::move(row));
  }
  return rows;
}

double number(const TextRow& row, const std::string& column, const std::filesystem::path& file) {
  const auto it = row.find(column);
  if (it == row.end() || it->second.empty()) {
    throw common::ConfigError(fmt::format("{}: a row has no value in column '{}'", file.string(), column));
  }
  return std::strtod(it->second.c_str(), nullptr);
}

std::string text(const TextRow& row, const std::string& column) {
  const auto it = row.find(column);
  return it == row.end() ? std::string() : it->second;
}

}  // namespace hs::validate
