// SPDX-License-Identifier: MIT
// `hemoscale bench NAME [--json FILE]`: run one benchmark, print what it measured.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "app/registry.hpp"
#include "app/task_dispatch.hpp"

namespace hs::app {

void add_bench_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<TaskArgs>();
  auto* cmd = cli.add_subcommand("bench", "Run a benchmark (speed vs the memory-bandwidth roofline and peer codes)");
  add_task_options(*cmd, *args, benchmarks());
  cmd->callback([&action, args] { action = [args] { return dispatch_task("benchmark", benchmarks(), *args); }; });
}

}  // namespace hs::app
