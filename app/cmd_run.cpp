// SPDX-License-Identifier: MIT
// `hemoscale run CASE_DIR`: read case.toml, dispatch on [case] type.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <mpi.h>

#include "app/commands.hpp"
#include "app/registry.hpp"
#include "common/config/config_file.hpp"
#include "common/errors.hpp"
#include "common/run_folder.hpp"

namespace hs::app {
namespace {

struct RunArgs {
  std::string case_dir;
  std::string output;
  bool resume = false;
  bool quiet = false;
  bool quick = false;
};

int run_case(const RunArgs& args) {
  namespace fs = std::filesystem;
  const fs::path dir = args.case_dir;
  const fs::path file = fs::is_directory(dir) ? dir / "case.toml" : dir;
  auto config = hs::common::ConfigFile::load(file);
  const auto types = case_types();
  std::string allowed;
  for (const auto& [name, entry] : types) allowed += (allowed.empty() ? "" : ", ") + name;
  auto root = config->root();
  auto section = root.section("case");
  const std::string type = section.string("type");
  const auto it = types.find(type);
  if (it == types.end()) section.fail("type", fmt::format("unknown case type (known: {})", allowed));
  if (args.resume && args.output.empty()) {
    throw hs::common::ConfigError("--resume needs --output RUN_DIR: the run folder to continue");
  }
  if (args.resume && hs::common::resume_finds_complete_run(args.output)) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) {
      fmt::print("{}: --resume: the run is already complete (summary.json written); nothing changed\n", args.output);
    }
    return 0;
  }
  hs::common::CaseRequest request{.case_dir = file.parent_path(),
                                  .config = config.get(),
                                  .output_dir = args.output.empty() ? std::nullopt : std::optional<fs::path>(args.output),
                                  .resume = args.resume,
                                  .quiet = args.quiet,
                                  .quick = args.quick};
  return it->second.run(request);
}

}  // namespace

void add_run_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = cli.add_subcommand("run", "Run one case folder (CASE_DIR/case.toml); outputs go to a new CASE_DIR/runs/run-NNN");
  cmd->add_option("CASE_DIR", args->case_dir, "case folder, or a case .toml file")->required();
  cmd->add_option("--output,-o", args->output, "run folder to write (must not exist, or with --resume: the run to continue)");
  cmd->add_flag("--resume", args->resume, "continue the run in --output from its last checkpoint");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress line");
  cmd->add_flag("--quick", args->quick, "coarse, short version of the case (for CI)");
  std::string types = "Case types ([case] type in case.toml):";
  std::size_t width = 0;   // the longest name and one space: every description starts in one column
  for (const auto& [name, entry] : case_types()) width = std::max(width, name.size() + 1);
  for (const auto& [name, entry] : case_types()) types += fmt::format("\n  {:<{}}{}", name, width, entry.help);
  cmd->footer(types);
  cmd->callback([&action, args] { action = [args] { return run_case(*args); }; });
}

}  // namespace hs::app
