// SPDX-License-Identifier: MIT
// A campaign's (Re, r*) dataset against the acceptance rules of the resolved campaign and published ranges.
#include "campaign/dataset_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"

namespace hs::campaign {
namespace {

bool same(double a, double b) { return std::abs(a - b) < 1e-9; }

/// Widens `r` to hold v; a NaN or infinite value (a broken row, reported as such) is left out.
void widen(Range& r, double v, bool& first) {
  if (!std::isfinite(v)) return;
  r.min = first ? v : std::min(r.min, v);
  r.max = first ? v : std::max(r.max, v);
  first = false;
}

/// Rows whose `settled` or `cd_settled` cell reads "false" (text columns, which read_csv gives as NaN).
int count_unsettled(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::vector<int> flags;
  int count = 0;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = common::split_csv_line(line);
    if (header) {
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c] == "settled" || cells[c] == "cd_settled") flags.push_back(static_cast<int>(c));
      }
      header = false;
      continue;
    }
    count += std::any_of(flags.begin(), flags.end(), [&](int c) {
      return static_cast<std::size_t>(c) < cells.size() && cells[static_cast<std::size_t>(c)] == "false";
    }) ? 1 : 0;
  }
  return count;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void read_published_ranges(const std::filesystem::path& file, DatasetExpectations& into) {
  std::ifstream in(file);
  if (!in) throw common::ConfigError(fmt::format("{}: cannot read the published ranges", file.string()));
  bool header = true;
  bool gamma = false;
  bool re_p = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \r") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> cells = common::split_csv_line(line);
    if (header) {
      if (cells != std::vector<std::string>{"quantity", "min", "max"}) break;
      header = false;
      continue;
    }
    if (cells.size() != 3) break;
    const Range range{std::strtod(cells[1].c_str(), nullptr), std::strtod(cells[2].c_str(), nullptr)};
    if (cells[0] == "gamma_plus") into.gamma_plus = range, gamma = true;
    if (cells[0] == "re_p") into.re_p = range, re_p = true;
  }
  if (!gamma || !re_p) {
    throw common::ConfigError(
        fmt::format("{}: needs the header quantity,min,max and the rows gamma_plus and re_p", file.string()));
  }
}

DatasetCheck check_resolved_dataset(const std::filesystem::path& csv, const DatasetExpectations& expected) {
  const common::CsvTable table = common::read_csv(csv);
  const std::vector<std::string> numeric{"re", "r_star", "gamma_plus", "u_r_plus", "re_p", "di", "di_spread",
                                         "cd", "cd_spread", "cl", "cl_spread", "periods", "dx_m"};
  std::map<std::string, int> col;
  for (const auto& name : numeric) {
    col[name] = table.column_index(name);
    if (col[name] < 0) throw common::ConfigError(fmt::format("resolved dataset: no column '{}'", name));
  }
  DatasetCheck check;
  check.rows = static_cast<int>(table.rows.size());
  check.rows_expected = static_cast<int>(expected.re.size() * expected.r_star.size());
  std::map<double, std::vector<double>> cd_re_p;   // r* -> Cd Re_p of its rows
  std::array<bool, 5> first{true, true, true, true, true};
  for (const auto& row : table.rows) {
    const auto at = [&](const char* name) { return row[static_cast<std::size_t>(col[name])]; };
    const double re = at("re");
    const double r_star = at("r_star");
    const auto problem = [&](std::string what) { check.problems.push_back({re, r_star, std::move(what)}); };
    for (const auto& name : numeric) {
      if (!std::isfinite(at(name.c_str()))) problem(fmt::format("{} is not a finite number", name));
    }
    if (!(at("di") > 0.0 && at("di") < 1.0)) problem(fmt::format("DI {} outside (0, 1)", at("di")));
    if (!(at("cd") > 0.0)) problem(fmt::format("Cd {} not along the flow past the held cell", at("cd")));
    if (!(at("cl") < 0.0)) problem(fmt::format("Cl {} not towards the axis", at("cl")));
    widen(check.gamma_plus, at("gamma_plus"), first[0]);
    widen(check.re_p, at("re_p"), first[1]);
    widen(check.di, at("di"), first[2]);
    widen(check.cd, at("cd"), first[3]);
    widen(check.cl, at("cl"), first[4]);
    const double scaled = at("cd") * at("re_p");
    if (std::isfinite(r_star) && std::isfinite(scaled) && scaled > 0.0) cd_re_p[r_star].push_back(scaled);
  }
  for (const double re : expected.re) {
    for (const double r_star : expected.r_star) {
      const bool present = std::any_of(table.rows.begin(), table.rows.end(), [&](const auto& row) {
        return same(row[static_cast<std::size_t>(col["re"])], re) && same(row[static_cast<std::size_t>(col["r_star"])], r_star);
      });
      if (!present) check.missing.push_back(fmt::format("Re {}, r* {}", re, r_star));
    }
  }
  check.unsettled = count_unsettled(csv);
  for (const auto& [r_star, values] : cd_re_p) {
    const double m = median(values);
    double deviation = 0.0;
    for (const double v : values) deviation = std::max(deviation, std::abs(v / m - 1.0));
    check.stokes.push_back({r_star, static_cast<int>(values.size()), m, deviation});
  }
  return check;
}

}  // namespace hs::campaign
