// SPDX-License-Identifier: MIT
// Starts the hemoscale executable in the background, for tests that interrupt a run the way a user would.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace hs::test {

/// `hemoscale ARGS` (HS_BIN, defined by the test target) with stdout and stderr going to `log`.
inline pid_t start_hemoscale(std::vector<std::string> args, const std::filesystem::path& log) {
  args.insert(args.begin(), HS_BIN);
  const pid_t pid = fork();
  if (pid != 0) return pid;
  std::FILE* out = std::freopen(log.c_str(), "w", stdout);
  if (out == nullptr || dup2(fileno(stdout), STDERR_FILENO) < 0) _exit(127);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  _exit(127);
}

/// Waits until `ready()` holds, polling; false after `timeout`.
inline bool wait_until(const std::function<bool()>& ready, std::chrono::seconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!ready()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

/// The exit code of a background run, -1 if a signal killed it.
inline int wait_for_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Number of lines of a text file (0 if it does not exist yet).
inline long line_count(const std::filesystem::path& file) {
  std::ifstream in(file);
  long n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

/// The whole text of a file.
inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace hs::test
