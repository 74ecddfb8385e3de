// SPDX-License-Identifier: MIT
// `hemoscale campaign CAMPAIGN_DIR`: run (or resume) every case of a campaign grid, then assemble its dataset.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "campaign/campaign_runner.hpp"
#include "common/errors.hpp"

namespace hs::app {
namespace {

struct CampaignArgs {
  std::string dir;
  bool status = false;
  bool retry_failed = false;
  bool reopen_done = false;
  bool quiet = false;
  int max_runs = -1;
};

/// The campaign folder, given as the folder or as its campaign.toml (as `run` takes a case folder or its file).
std::filesystem::path campaign_dir(const std::filesystem::path& given) {
  if (!std::filesystem::is_regular_file(given)) return given;
  if (given.filename() != "campaign.toml") {
    throw hs::common::ConfigError(fmt::format("{}: not a campaign; give the campaign folder or its campaign.toml",
                                              given.string()));
  }
  return given.parent_path().empty() ? std::filesystem::path(".") : given.parent_path();
}

int run_campaign(const CampaignArgs& args) {
  const auto spec = hs::campaign::read_campaign_spec(campaign_dir(args.dir));
  hs::campaign::CampaignRunner runner(spec, {.executable = std::filesystem::read_symlink("/proc/self/exe"),
                                             .retry_failed = args.retry_failed,
                                             .reopen_done = args.reopen_done,
                                             .show_progress = !args.quiet,   // a line on a terminal, dated lines in a log
                                             .max_runs = args.max_runs});
  if (args.status) {
    std::fputs(runner.status_table().c_str(), stdout);
    return 0;
  }
  const int failed = runner.run();
  std::fputs(runner.status_table().c_str(), stdout);
  std::printf("dataset: %s\n", spec.dataset_file.string().c_str());
  return failed == 0 ? 0 : 1;
}

}  // namespace

void add_campaign_command(CLI::App& cli, Action& action) {
  auto args = std::make_shared<CampaignArgs>();
  auto* cmd = cli.add_subcommand("campaign", "Run or resume a campaign (CAMPAIGN_DIR/campaign.toml): a grid of runs and their dataset");
  cmd->add_option("CAMPAIGN_DIR", args->dir, "campaign folder, or its campaign.toml")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_flag("--status", args->status, "print what is done, failed and left; run nothing");
  cmd->add_flag("--retry-failed", args->retry_failed, "run failed runs again");
  cmd->add_flag("--reopen-done", args->reopen_done,
                "run finished runs again, from their last checkpoint where they have one (after a stricter stopping rule)");
  cmd->add_option("--max-runs", args->max_runs, "start at most this many runs in this invocation");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress line and no per-run lines on stderr (the status table still prints)");
  cmd->callback([&action, args] { action = [args] { return run_campaign(*args); }; });
}

}  // namespace hs::app
