// SPDX-License-Identifier: MIT
// Reading and sampling the AI-Feynman table, and the symbolic judge of recovery.
#include "regression/feynman_table.hpp"

#include <cctype>
#include <fstream>
#include <map>
#include <random>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "regression/infix.hpp"
#include "regression/polynomial.hpp"
#include "regression/simplify.hpp"

namespace hs::regression {
namespace {

/// Splits one CSV line at commas outside double quotes; quotes are removed.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (const char ch : line) {
    if (ch == '"') {
      quoted = !quoted;
    } else if (ch == ',' && !quoted) {
      out.emplace_back();
    } else if (ch != '\r') {
      out.back() += ch;
    }
  }
  return out;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

/// The table's Python syntax in this parser's: "**" -> "^", and whole identifiers renamed (pi -> its value,
/// arcsin -> asin, ln -> log); a variable that merely contains "pi" or "ln" (e.g. "lnT") is left alone.
std::string python_to_infix(const std::string& formula) {
  static const std::map<std::string, std::string> renamed{{"pi", "3.141592653589793"}, {"arcsin", "asin"}, {"ln", "log"}};
  const std::string text = replace_all(formula, "**", "^");
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto is_start = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    const auto is_part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    const bool after_digit = i > 0 && (std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.');
    if (!is_start(text[i]) || after_digit) {   // after_digit: the "e" of 1e-3 is not an identifier
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && is_part(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    const auto it = renamed.find(word);
    out += it == renamed.end() ? word : it->second;
    i = end;
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  const auto e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string{} : s.substr(b, e - b + 1);
}

/// "x1:[1,5]; x2:[1,5]" -> names and ranges; throws std::invalid_argument on a malformed item.
void parse_ranges(const std::string& text, FeynmanEquation& eq) {
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = trim(text.substr(start, end - start));
    start = end + 1;
    if (item.empty()) continue;
    const auto colon = item.find(':');
    const auto open = item.find('[');
    const auto comma = item.find(',', open);
    if (colon == std::string::npos || open == std::string::npos || comma == std::string::npos || item.back() != ']') {
      throw std::invalid_argument(fmt::format("range '{}' is not NAME:[LO,HI]", item));
    }
    eq.names.push_back(trim(item.substr(0, colon)));
    eq.lo.push_back(std::stod(item.substr(open + 1, comma - open - 1)));
    eq.hi.push_back(std::stod(item.substr(comma + 1, item.size() - comma - 2)));
  }
}

}  // namespace

std::vector<FeynmanEquation> read_feynman_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw hs::common::ConfigError(fmt::format("{}: cannot read the Feynman table", file.string()));
  std::string line;
  std::getline(in, line);
  const auto header = csv_fields(line);
  auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (trim(header[i]) == name) return i;
    }
    throw hs::common::ConfigError(fmt::format("{}: no column '{}' in the header", file.string(), name));
  };
  const std::size_t c_id = column("feynman_id"), c_formula = column("formula_python");
  const std::size_t c_ranges = column("variables_with_uniform_ranges");
  std::vector<FeynmanEquation> out;
  for (int number = 2; std::getline(in, line); ++number) {
    if (trim(line).empty()) continue;
    const auto fields = csv_fields(line);
    try {
      if (fields.size() != header.size()) throw std::invalid_argument(fmt::format("{} fields, header has {}", fields.size(), header.size()));
      FeynmanEquation eq;
      eq.id = trim(fields[c_id]);
      eq.formula = trim(fields[c_formula]);
      parse_ranges(fields[c_ranges], eq);
      eq.truth = parse_infix(python_to_infix(eq.formula), eq.names);
      out.push_back(std::move(eq));
    } catch (const std::exception& e) {
      throw hs::common::ConfigError(fmt::format("{}:{}: {}", file.string(), number, e.what()));
    }
  }
  if (out.empty()) throw hs::common::ConfigError(fmt::format("{}: no equations", file.string()));
  return out;
}

FeynmanSample sample_feynman(const FeynmanEquation& eq, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  FeynmanSample s{std::vector<std::vector<double>>(eq.names.size(), std::vector<double>(n)), std::vector<double>(n)};
  std::vector<double> point(eq.names.size());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < point.size(); ++j) {
      point[j] = s.x[j][i] = std::uniform_real_distribution<double>(eq.lo[j], eq.hi[j])(rng);
    }
    s.y[i] = eq.truth.evaluate(point.data());
  }
  return s;
}

bool symbolic_match(const Expression& model, const Expression& truth, const std::vector<std::string>& names) {
  constexpr auto mode = SimplifyMode::Algebraic;
  auto canonical = [&](const Expression& e) {
    return to_infix(simplify(snap_constants(expand_polynomials(simplify(e, mode))), mode), names);
  };
  return canonical(model) == canonical(truth);
}

}  // namespace hs::regression
