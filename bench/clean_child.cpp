// SPDX-License-Identifier: MIT
#include "bench/clean_child.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

extern char** environ;   // POSIX: the environment the child starts from

namespace hs::bench {

bool run_clean_child(const std::vector<std::string>& argv, const std::vector<std::string>& set) {
  std::vector<std::string> env_text;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string v = *e;
    bool drop = v.rfind("OMPI_", 0) == 0 || v.rfind("PMIX_", 0) == 0;
    for (const std::string& s : set) drop = drop || v.rfind(s.substr(0, s.find('=') + 1), 0) == 0;
    if (!drop) env_text.push_back(v);
  }
  env_text.insert(env_text.end(), set.begin(), set.end());
  std::vector<char*> envp;
  for (auto& v : env_text) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::vector<std::string> args = argv;
  std::vector<char*> argp;
  for (auto& a : args) argp.push_back(a.data());
  argp.push_back(nullptr);
  pid_t pid = 0;
  if (const int err = posix_spawnp(&pid, argp[0], nullptr, nullptr, argp.data(), envp.data()); err != 0) {
    throw std::runtime_error(fmt::format("cannot start {}: {}", argv.front(), std::strerror(err)));
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string this_executable() { return std::filesystem::read_symlink("/proc/self/exe").string(); }

}  // namespace hs::bench
