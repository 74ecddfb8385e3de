// SPDX-License-Identifier: MIT
// Each subcommand of the `hemoscale` CLI adds itself to the parser; its file holds all its code.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace hs::app {

/// What a parsed subcommand runs; returns the exit code.
using Action = std::function<int()>;

void add_run_command(CLI::App& cli, Action& action);
void add_bench_command(CLI::App& cli, Action& action);
void add_validate_command(CLI::App& cli, Action& action);
void add_campaign_command(CLI::App& cli, Action& action);
void add_fit_command(CLI::App& cli, Action& action);
void add_study_command(CLI::App& cli, Action& action);

}  // namespace hs::app
