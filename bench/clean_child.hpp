// SPDX-License-Identifier: MIT
// A child process outside this process's MPI job, for the benches that measure in a fresh process (its own peak
// memory) or on other rank counts (mpiexec): this process is an MPI singleton or rank whose OMPI_/PMIX_ variables
// would make the child try to join it.
#pragma once

#include <string>
#include <vector>

namespace hs::bench {

/// Runs `argv` (argv[0] a path, or a name looked up on PATH) with this process's environment less every OMPI_* and
/// PMIX_* variable and less the names `set` gives, plus `set` ("NAME=value"); waits for it. True when it exited 0.
/// Throws std::runtime_error when it cannot be started.
[[nodiscard]] bool run_clean_child(const std::vector<std::string>& argv, const std::vector<std::string>& set);

/// This executable's path (what /proc/self/exe names), for a child that runs it again under mpiexec.
[[nodiscard]] std::string this_executable();

}  // namespace hs::bench
