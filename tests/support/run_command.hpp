// SPDX-License-Identifier: MIT
// Runs the hemoscale executable as a user would (tests that check exit codes and messages).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace hs::test {

struct CommandResult {
  int code;            // exit code, -1 if killed by a signal
  std::string output;  // stdout and stderr together
};

/// A shell command line, stdout and stderr captured together.
inline CommandResult run_shell(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) out += buf.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// `hemoscale ARGS`, with HS_BIN (the executable's path) defined by the test target.
inline CommandResult run_hemoscale(const std::string& args) { return run_shell(std::string(HS_BIN) + " " + args); }

}  // namespace hs::test
