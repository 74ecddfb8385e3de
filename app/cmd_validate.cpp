// SPDX-License-Identifier: MIT
// `hemoscale validate NAME [--json FILE]`: run one validation against published data.
#include <memory>

#include "app/commands.hpp"
#include "app/registry.hpp"
#include "app/task_dispatch.hpp"

namespace hs::app {

void add_validate_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<TaskArgs>();
  auto* cmd = cli.add_subcommand("validate", "Run a validation against analytic or published data");
  add_task_options(*cmd, *args, validations());
  cmd->callback([&action, args] { action = [args] { return dispatch_task("validation", validations(), *args); }; });
}

}  // namespace hs::app
