// SPDX-License-Identifier: MIT
// Ctrl-C or `kill` asks a long run to stop cleanly: it finishes its step, writes a checkpoint and exits, so
// `--resume` continues from where it stopped instead of from the last periodic checkpoint.
#pragma once

#include <csignal>
#include <stdexcept>
#include <string>

namespace hs::common {

/// While alive, SIGINT and SIGTERM set a flag instead of ending the process; a second signal ends it at once.
/// Held only around loops that look at the flag, so everything else still dies on Ctrl-C.
class StopRequestScope {
 public:
  StopRequestScope();
  ~StopRequestScope();
  StopRequestScope(const StopRequestScope&) = delete;
  StopRequestScope& operator=(const StopRequestScope&) = delete;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

/// The signal that asked this process to stop (SIGINT or SIGTERM), 0 while none did.
int stop_signal();

/// Thrown after the run has saved its checkpoint; the CLI exits with 128 + the signal, as a shell would.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(const std::string& what, int signal) : std::runtime_error(what), signal_(signal) {}
  [[nodiscard]] int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

}  // namespace hs::common
