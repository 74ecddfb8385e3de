// SPDX-License-Identifier: MIT
// A numeric CSV table.
#include "study/csv_table.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::study {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(field);
  return out;
}

}  // namespace

CsvTable read_csv_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw hs::common::ConfigError(fmt::format("{}: no such table", file.string()));
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) throw hs::common::ConfigError(fmt::format("{}: empty table", file.string()));
  t.columns = split(line);
  long number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const auto fields = split(line);
    if (fields.size() != t.columns.size()) {
      throw hs::common::ConfigError(fmt::format("{}:{}: {} fields, the header has {}", file.string(), number, fields.size(), t.columns.size()));
    }
    std::vector<double> row;
    row.reserve(fields.size());
    for (const auto& f : fields) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      if (end == f.c_str()) throw hs::common::ConfigError(fmt::format("{}:{}: '{}' is not a number", file.string(), number, f));
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace hs::study
