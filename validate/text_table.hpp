// SPDX-License-Identifier: MIT
// A small CSV file (a dataset, a reference table) read as text cells under their column names, for validations that
// mix numbers and words ("tank-treading", "true").
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hs::validate {

using TextRow = std::map<std::string, std::string>;

/// Every row of `file` under the first line's names; lines starting with '#' and blank lines are skipped.
/// ConfigError when the file cannot be read.
std::vector<TextRow> read_text_table(const std::filesystem::path& file);

/// The number in `column` of `row`; ConfigError naming the file and column when it is missing or empty.
double number(const TextRow& row, const std::string& column, const std::filesystem::path& file);

/// The text in `column` of `row` ("" when missing).
std::string text(const TextRow& row, const std::string& column);

}  // namespace hs::validate
