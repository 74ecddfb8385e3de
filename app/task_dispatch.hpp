// SPDX-License-Identifier: MIT
// Shared parsing and dispatch for the two NAME-keyed subcommands, bench and validate.
#pragma once

#include <map>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/registry.hpp"
#include "common/errors.hpp"

namespace hs::app {

struct TaskArgs {
  std::string name;
  std::string json;
  std::string extra;
  std::string suspension_viscosity;
  bool quick = false;
  std::string dataset;
  double tighten = 1.0;
};

inline void add_task_options(CLI::App& cmd, TaskArgs& args, const std::map<std::string, TaskEntry>& known) {
  std::string list;
  for (const auto& [name, entry] : known) list += fmt::format("\n  {:<12} {}", name, entry.help);
  cmd.add_option("NAME", args.name, "one of:" + (list.empty() ? std::string(" (none yet)") : list))->required();
  cmd.add_option("--json", args.json, "also write the results as JSON to this file");
  cmd.add_flag("--quick", args.quick, "a shorter version (CI)");
  cmd.add_option("--closures", args.extra, "closure set by name or file (validations that use closures)");
  cmd.add_option("--suspension-viscosity", args.suspension_viscosity,
                 "none | einstein | pries_bulk: the cells' stress in CFD-DEM validations (pries: default einstein; pries_bulk is a labelled sensitivity study)");
  cmd.add_option("--dataset", args.dataset, "the dataset CSV a dataset validation reads (default: the committed one)");
  cmd.add_option("--tighten", args.tighten,
                 "for tests of the failure path: every band divided by F, every target multiplied by F (a result, "
                 "never a validation)")
      ->check(CLI::PositiveNumber);
}

inline int dispatch_task(const char* kind, const std::map<std::string, TaskEntry>& known, const TaskArgs& args) {
  const auto it = known.find(args.name);
  if (it == known.end()) {
    std::string list;
    for (const auto& [name, entry] : known) list += (list.empty() ? "" : ", ") + name;
    throw hs::common::ConfigError(fmt::format("unknown {} '{}' (known: {})", kind, args.name, list.empty() ? "none yet" : list));
  }
  hs::common::TaskOptions options;
  if (!args.json.empty()) options.json_file = args.json;
  options.quick = args.quick;
  options.extra = args.extra;
  options.suspension_viscosity = args.suspension_viscosity;
  options.tighten = args.tighten;
  if (!args.dataset.empty()) options.dataset = args.dataset;
  return it->second.run(options);
}

}  // namespace hs::app
