// SPDX-License-Identifier: MIT
// Test helpers that edit the text of a shipped case file: read it, replace a line, write it to a temporary folder.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace hs::test {

/// The text of the shipped case cases/resolved/`folder`/case.toml.
inline std::string shipped_case_text(const std::string& folder) {
  std::ifstream in(std::filesystem::path(HS_SOURCE_DIR) / "cases/resolved" / folder / "case.toml");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// `text` with the first `from` replaced by `to` (a test failure if `from` does not occur).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

/// `text` written as case.toml into a fresh temporary folder named after `name`, which is returned.
inline std::filesystem::path write_case_text(const std::string& name, const std::string& text) {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() / ("hs_case_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << text;
  return dir;
}

}  // namespace hs::test
