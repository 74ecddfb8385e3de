// SPDX-License-Identifier: MIT
// `hemoscale study NAME [--quick] [--output DIR]`: run a study's cases (resumable) and write its table and figures.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "app/registry.hpp"
#include "common/errors.hpp"

namespace hs::app {
namespace {

struct StudyArgs {
  std::string name;
  std::string output;
  bool quick = false;
};

int dispatch_study(const StudyArgs& args) {
  const auto known = studies();
  const auto it = known.find(args.name);
  if (it == known.end()) {
    std::string list;
    for (const auto& [name, entry] : known) list += (list.empty() ? "" : ", ") + name;
    throw hs::common::ConfigError(fmt::format("unknown study '{}' (known: {})", args.name, list));
  }
  hs::common::StudyOptions options;
  if (!args.output.empty()) options.output_dir = args.output;
  options.quick = args.quick;
  return it->second.run(options);
}

}  // namespace

void add_study_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<StudyArgs>();
  auto* cmd = cli.add_subcommand("study", "Run a study (several committed cases; resumable) and write its table and figures");
  std::string list;
  for (const auto& [name, entry] : studies()) list += fmt::format("\n  {:<12} {}", name, entry.help);
  cmd->add_option("NAME", args->name, "one of:" + list)->required();
  cmd->add_option("--output,-o", args->output, "folder of the runs, the table and the figures (a finished run there is kept)");
  cmd->add_flag("--quick", args->quick, "every run --quick (20 CFD steps): no steady-state checks, no figures (CI)");
  cmd->callback([&action, args] { action = [args] { return dispatch_study(*args); }; });
}

}  // namespace hs::app
