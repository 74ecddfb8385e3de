// SPDX-License-Identifier: MIT
// A closure file checked against its reference table (STYLE R9), with the evaluator a solver uses.
#include "closures/closure_check.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "closures/closure_file.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"
#include "regression/compiled_program.hpp"

namespace hs::closures {

namespace hsr = hs::regression;

std::string check_closure(const std::filesystem::path& file) {
  const ClosureFile c = ClosureFile::load(file);
  std::string out = fmt::format("{} ({}): {} = {}\n", c.name, c.kind, c.output, c.expression);
  for (std::size_t j = 0; j < c.variables.size(); ++j) {
    out += fmt::format("  {} in [{}, {}]: {}\n", c.variables[j], c.validity[j].lo, c.validity[j].hi, c.definitions[j]);
  }
  const auto table = file.parent_path() / (c.name + ".reference.csv");
  if (!std::filesystem::exists(table)) return out + "  (no reference table beside it)\n";
  const auto csv = hs::common::read_csv(table);
  const hsr::CompiledProgram program(c.parsed());
  std::vector<double> x(c.variables.size());
  for (const auto& row : csv.rows) {
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = row[static_cast<std::size_t>(csv.column_index(c.variables[j]))];
    const double expected = row[static_cast<std::size_t>(csv.column_index("expected"))];
    const double got = program.evaluate_point(x.data());
    // The table was written by the same evaluator; 1e-12 relative allows for a rebuilt compiler's rounding.
    if (!(std::abs(got - expected) <= 1e-12 * std::max(std::abs(expected), 1e-300))) {
      throw hs::common::NumericalError(fmt::format("{}: expression gives {} where {} expects {}", file.string(), got,
                                                   table.string(), expected));
    }
  }
  return out + fmt::format("  reproduces its reference table ({} rows)\n", csv.rows.size());
}

}  // namespace hs::closures
