// SPDX-License-Identifier: MIT
// `hemoscale fit FIT.toml`: learn a closure formula from a dataset by symbolic regression.
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "closures/closure_check.hpp"
#include "closures/closure_fit.hpp"
#include "closures/fit_request.hpp"
#include "common/errors.hpp"
#include "common/run_folder.hpp"

namespace hs::app {
namespace {

struct FitArgs {
  std::string fit_file;
  std::string check;
  std::string output;
  bool quiet = false;
  bool no_plot = false;
};

int run_fit_command(const FitArgs& args) {
  namespace fs = std::filesystem;
  if (!args.check.empty()) {
    fmt::print("{}", hs::closures::check_closure(args.check));
    return 0;
  }
  if (args.fit_file.empty()) throw hs::common::ConfigError("hemoscale fit: give FIT_TOML (or --check CLOSURE_TOML)");
  const auto request = hs::closures::read_fit_request(args.fit_file);
  const fs::path fit_dir = fs::absolute(args.fit_file).parent_path();
  const auto folder = args.output.empty() ? hs::common::RunFolder::create_new(fit_dir / "runs", "fit")
                                          : hs::common::RunFolder::create_exact(args.output);
  fs::remove(folder.vtk_dir());          // a fit writes no fields and no checkpoints
  fs::remove(folder.checkpoint_dir());
  fs::copy_file(args.fit_file, folder.file("fit.toml"));
  hs::closures::run_fit(request, folder.path(), args.quiet);
  const bool wanted = request.plot && !args.no_plot;
  const bool plotted = wanted && hs::closures::render_fit_report(folder.path());
  if (!args.quiet) {
    const char* why_not = wanted ? " (no report.png: /usr/bin/python3 with matplotlib not found)" : "";
    fmt::print("wrote {}{}\n", (folder.path() / (request.name + ".toml")).string(), plotted ? " and report.png" : why_not);
  }
  return 0;
}

}  // namespace

void add_fit_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<FitArgs>();
  auto* cmd = cli.add_subcommand("fit", "Learn a closure formula from a dataset by symbolic regression (FIT.toml)");
  cmd->add_option("FIT_TOML", args->fit_file, "fit file: dataset, target, features, function set, budget, seed");
  cmd->add_option("--check", args->check, "only load and check a closure file (and its reference table)");
  cmd->add_option("--output,-o", args->output, "folder to write (must not exist); default FIT_DIR/runs/fit-NNN");
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing");
  cmd->add_flag("--no-plot", args->no_plot, "do not render report.png");
  cmd->callback([&action, args] { action = [args] { return run_fit_command(*args); }; });
}

}  // namespace hs::app
