// SPDX-License-Identifier: MIT
// Shared helpers of the case CLI tests: run the hemoscale binary, and write a shipped case with one line replaced.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "resolved/cases/case_text_helpers.hpp"

namespace hs::test {

struct CliResult {
  int code;
  std::string output;
};

/// Runs `HS_BIN args` and returns its exit code and combined stdout/stderr.
inline CliResult run_hemoscale(const std::string& args) {
  const std::string cmd = std::string(HS_BIN) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe) != nullptr) out += buf.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// The shipped case cases/resolved/`folder`/case.toml with one line replaced (`from` must occur in it), written to a
/// fresh temporary folder named after `name`, which is returned.
inline std::filesystem::path write_case_variant(const std::string& folder, const std::string& name,
                                                const std::string& from, const std::string& to) {
  return write_case_text(name, replaced(shipped_case_text(folder), from, to));
}

}  // namespace hs::test
