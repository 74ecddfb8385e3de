// SPDX-License-Identifier: MIT
// Runs every point of a campaign grid as its own `hemoscale run`, a few at a time, unattended.
#include "campaign/campaign_runner.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "campaign/case_template.hpp"
#include "campaign/dataset_writer.hpp"
#include "campaign/invocation_log.hpp"
#include "campaign/run_archive.hpp"
#include "common/errors.hpp"
#include "common/io/checkpoint.hpp"
#include "common/progress.hpp"
#include "common/stop_request.hpp"

namespace hs::campaign {
namespace {

using Clock = std::chrono::steady_clock;
/// Exit code of a run that reached its cap (max time) without meeting its settling rule.
constexpr int kStoppedAtCap = 1;

/// A run that stopped on SIGINT / SIGTERM after writing its checkpoint exits with 128 + the signal.
bool stopped_on_request(int code) { return code == 128 + SIGINT || code == 128 + SIGTERM; }

/// Starts `hemoscale run` for one record; its console goes to console.txt. The child dies with the campaign
/// (PR_SET_PDEATHSIG), so an interrupted campaign leaves no orphan behind; the run resumes next time.
pid_t spawn_run(const CampaignOptions& options, const RunRecord& r, int threads) {
  std::vector<std::string> args{options.executable.string(), "run", r.case_file().string(), "--output",
                                r.output_dir().string(), "--quiet"};
  if (r.state == RunState::resumable) args.emplace_back("--resume");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid > 0) return pid;
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  setpgid(0, 0);   // Ctrl-C reaches the campaign only, which asks each run once to stop (a second signal kills)
  const int fd = ::open(r.console_file().c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  setenv("OMP_NUM_THREADS", std::to_string(threads).c_str(), 1);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  _exit(127);
}

/// How far a run has simulated: the first field of the last row of its timeseries.csv when that column is time_s
/// (the cell cases), e.g. "0.58 s"; "" otherwise.
std::string simulated_time(const RunRecord& r) {
  std::ifstream in(r.output_dir() / "timeseries.csv");
  std::string header, line, last;
  if (!std::getline(in, header) || header.rfind("time_s,", 0) != 0) return "";
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  if (last.empty()) return "";
  return fmt::format("{:.3g} s", std::strtod(last.c_str(), nullptr));
}

/// Wall seconds the runs not yet finished will take, roughly: the median wall time of the done runs (a run's own
/// attempts added up) for each, in rounds of `jobs` at a time. Runs differ (longer periods at small r*, more steps
/// at small Re) and part-done ones count whole. Negative when no run is done yet.
double estimate_left_s(const std::vector<RunRecord>& runs, int jobs) {
  std::vector<double> done;
  int left = 0;
  for (const auto& r : runs) {
    if (r.state == RunState::done) done.push_back(r.wall_s);
    if (r.state == RunState::pending || r.state == RunState::resumable || r.state == RunState::running) ++left;
  }
  if (done.empty()) return -1.0;
  std::sort(done.begin(), done.end());
  const std::size_t n = done.size();
  const double median = n % 2 == 1 ? done[n / 2] : 0.5 * (done[n / 2 - 1] + done[n / 2]);
  return median * std::ceil(static_cast<double>(left) / jobs);
}

/// The last line starting with "error:" or "numerical failure:" in the run's console output.
std::string failure_reason(const RunRecord& r, int code) {
  std::ifstream in(r.console_file());
  std::string line, reason;
  while (std::getline(in, line)) {
    if (line.rfind("error:", 0) == 0 || line.rfind("numerical failure:", 0) == 0 || line.rfind("internal error:", 0) == 0) {
      reason = line;
    }
  }
  return reason.empty() ? fmt::format("exit code {} (see {})", code, r.console_file().string()) : reason;
}

}  // namespace

CampaignRunner::CampaignRunner(CampaignSpec spec, CampaignOptions options)
    : spec_(std::move(spec)), options_(std::move(options)) {}

std::vector<RunRecord> CampaignRunner::records(bool prepare) const {
  std::vector<RunRecord> out;
  for (const auto& p : grid_points(spec_)) {
    const std::string name = run_name(spec_, p);
    const auto dir = spec_.dir / "runs" / name;
    RunRecord r = read_run_record(dir, name);
    if (!prepare) {
      out.push_back(std::move(r));
      continue;
    }
    std::filesystem::create_directories(dir);
    if (!spec_.archive_dir.empty() && restore_run(r, spec_.archive_dir)) r = read_run_record(dir, name);
    // A run never started follows campaign.toml as it is now (an override added, the template edited); one that
    // has started keeps the case it started with.
    const bool never_started = r.state == RunState::pending && r.attempts == 0 && !std::filesystem::exists(r.output_dir());
    if (never_started || !std::filesystem::exists(dir / "case.toml")) write_run_case(spec_, p, dir / "case.toml");
    out.push_back(std::move(r));
  }
  return out;
}

std::string CampaignRunner::status_table() const {
  auto runs = records(false);   // only looks: writes no folder, case file or archived run
  std::map<RunState, int> count;
  std::string out = fmt::format("{:<44} {:<10} {:>10} {:>8} {:>10}  {}\n", "run", "state", "wall", "attempts",
                                "simulated", "reason");
  for (auto& r : runs) {
    // Not yet brought back from the archive (a fresh clone): the next `hemoscale campaign` restores it.
    const bool archived = !spec_.archive_dir.empty() && r.state == RunState::pending && r.attempts == 0 &&
                          !std::filesystem::exists(r.output_dir()) && std::filesystem::exists(spec_.archive_dir / r.name);
    const bool archived_done = archived && std::filesystem::exists(spec_.archive_dir / r.name / "status.json");
    if (archived_done) {   // its wall time and attempts as archived, so the totals below count it
      const RunRecord kept = read_run_record(spec_.archive_dir / r.name, r.name);
      r.wall_s = kept.wall_s;
      r.attempts = kept.attempts;
    }
    ++count[archived ? (archived_done ? RunState::done : RunState::resumable) : r.state];
    const std::string state = archived ? (archived_done ? "done*" : "resumable*") : to_string(r.state);
    out += fmt::format("{:<44} {:<10} {:>10} {:>8} {:>10}  {}\n", r.name, state,
                       r.wall_s > 0 ? common::Progress::format_duration(r.wall_s) : "", r.attempts, simulated_time(r),
                       r.reason);
  }
  out += fmt::format("{} runs: {} done, {} failed, {} running, {} resumable, {} pending{}\n", runs.size(),
                     count[RunState::done], count[RunState::failed], count[RunState::running],
                     count[RunState::resumable], count[RunState::pending],
                     spec_.archive_dir.empty() ? "" : " (*: in the archive, brought back by the next `hemoscale campaign`)");
  double wall_total = 0.0;
  for (const auto& r : runs) wall_total += r.wall_s;
  const int left = count[RunState::running] + count[RunState::resumable] + count[RunState::pending];
  out += fmt::format("wall time of the runs so far {} ({} thread{} per run)", common::Progress::format_duration(wall_total),
                     spec_.threads_per_job, spec_.threads_per_job == 1 ? "" : "s");
  const InvocationTotals campaign = read_invocation_totals(invocation_file(spec_));
  if (campaign.invocations > 0) {
    out += fmt::format("; of the campaign {} over {} invocation{} ({})",
                       common::Progress::format_duration(campaign.wall_s), campaign.invocations,
                       campaign.invocations == 1 ? "" : "s", invocation_file(spec_).string());
  }
  const double estimate = estimate_left_s(runs, spec_.jobs);
  if (estimate >= 0.0 && left > 0) {
    out += fmt::format("; {} left, roughly {} at {} at a time (the done runs' median each)", left,
                       common::Progress::format_duration(estimate), spec_.jobs);
  }
  out += "\n";
  return out;
}

int CampaignRunner::run() {
  auto runs = records(true);
  const auto points = grid_points(spec_);   // points[i] is runs[i]'s
  std::vector<std::size_t> queue;

  int finished = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].state == RunState::failed && options_.retry_failed) {
      runs[i].state = RunState::pending;
      // It starts afresh, so from campaign.toml as it is now: an override added to fix the failure applies.
      write_run_case(spec_, points[i], runs[i].dir / "case.toml");
    }
    if (runs[i].state == RunState::done && options_.reopen_done) {
      const bool resumable = common::Checkpoint::exists(runs[i].output_dir() / "checkpoint");
      runs[i].state = resumable ? RunState::resumable : RunState::pending;   // pending: afresh, its output set aside
      runs[i].reason.clear();
      std::filesystem::remove(runs[i].dir / "status.json");   // on disk too: an interrupted resume stays reopened
      if (!spec_.archive_dir.empty()) forget_archived_run(runs[i], spec_.archive_dir);   // and in the archive
      write_run_status(runs[i]);
    }
    if (runs[i].state == RunState::pending || runs[i].state == RunState::resumable) queue.push_back(i);
    if (runs[i].state == RunState::done && !spec_.archive_dir.empty() &&
        !std::filesystem::exists(spec_.archive_dir / runs[i].name / "status.json")) {
      archive_finished_run(runs[i], spec_.archive_dir);   // done before the archive existed
    }
  }
  write_dataset(spec_, runs);   // the rows of the runs done now (reopened runs drop out until they finish again)
  std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running;
  int started = 0;
  std::size_t next = 0;
  // Runs take minutes to hours: in a log every finished run is worth a line.
  common::Progress progress(fmt::format("campaign {}", spec_.name), static_cast<long>(queue.size()), options_.show_progress,
                            std::chrono::seconds(0));
  progress.set_eta_estimate([&](long) { return estimate_left_s(runs, spec_.jobs); });
  if (!queue.empty()) progress.update(0);   // a finished campaign says nothing
  std::optional<InvocationLog> invocation;   // only an invocation that runs something is worth recording
  if (!queue.empty()) {
    std::filesystem::create_directories(invocation_file(spec_).parent_path());
    invocation.emplace(invocation_file(spec_));
  }
  auto last_touch = Clock::now();
  const common::StopRequestScope stop_requests;
  bool stop_forwarded = false;
  while (next < queue.size() || !running.empty()) {
    while (common::stop_signal() == 0 && next < queue.size() && static_cast<int>(running.size()) < spec_.jobs &&
           (options_.max_runs < 0 || started < options_.max_runs)) {
      const std::size_t i = queue[next++];
      if (runs[i].state == RunState::pending) set_aside_output(runs[i]);
      std::filesystem::remove(runs[i].dir / "status.json");   // a retried run is no longer "failed" in --status
      runs[i].attempts += 1;
      write_run_status(runs[i]);   // attempts.json: counts attempts across interruptions
      const pid_t pid = spawn_run(options_, runs[i], spec_.threads_per_job);
      running[pid] = {i, Clock::now()};
      runs[i].state = RunState::running;   // attempts.json names the process, for --status
      runs[i].pid = pid;
      write_run_status(runs[i]);
      ++started;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);   // polled, so a stop request is never missed
    if (common::stop_signal() != 0 && !stop_forwarded) {
      for (const auto& entry : running) kill(entry.first, SIGTERM);   // each run checkpoints and exits
      stop_forwarded = true;
    }
    if (pid == 0 || (pid < 0 && errno == EINTR)) {
      // Once a minute: a campaign killed without warning loses at most that much of its recorded wall time.
      if (invocation && Clock::now() - last_touch > std::chrono::minutes(1)) {
        invocation->touch(finished);
        last_touch = Clock::now();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      continue;
    }
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    auto& r = runs[it->second.first];
    r.wall_s += std::chrono::duration<double>(Clock::now() - it->second.second).count();
    r.pid = 0;
    running.erase(it);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      r.state = RunState::done;
      r.reason.clear();
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == kStoppedAtCap && std::filesystem::exists(r.summary_file())) {
      r.state = RunState::done;   // the case file's documented cap: the summary says "settled": false
      r.reason = "stopped at its cap before settling";
    } else if (WIFEXITED(status) && stopped_on_request(WEXITSTATUS(status))) {
      r.state = RunState::resumable;   // it saved its checkpoint on the way out
    } else if (WIFEXITED(status)) {
      r.state = RunState::failed;
      r.reason = failure_reason(r, WEXITSTATUS(status));
    } else {
      // Killed by a signal (the machine, the user): not the run's fault; it resumes next time.
      r.state = common::Checkpoint::exists(r.output_dir() / "checkpoint") ? RunState::resumable : RunState::pending;
    }
    write_run_status(r);
    if (!spec_.archive_dir.empty() && r.state == RunState::done) archive_finished_run(r, spec_.archive_dir);
    if (!spec_.archive_dir.empty() && r.state == RunState::resumable) archive_checkpoint(r, spec_.archive_dir);
    if (!spec_.archive_dir.empty() && r.state == RunState::failed) forget_archived_run(r, spec_.archive_dir);
    progress.note(fmt::format("{}: {} after {}{}", r.name, to_string(r.state),
                              common::Progress::format_duration(r.wall_s), r.reason.empty() ? "" : " (" + r.reason + ")"));
    // A run stopped on request or killed is not finished: the progress line (and its ETA) counts only those that are.
    if (r.state == RunState::done || r.state == RunState::failed) progress.update(++finished);
    if (invocation) invocation->touch(finished);
    write_dataset(spec_, runs);
  }
  progress.finish();
  write_dataset(spec_, runs);
  if (invocation) invocation->touch(finished);
  if (const int signal = common::stop_signal()) {
    throw common::RunInterrupted(fmt::format("campaign {} stopped by signal {}; its runs saved checkpoints, run the same "
                                             "command again to continue", spec_.name, signal), signal);
  }
  int failed = 0;
  for (const auto& r : runs) failed += r.state == RunState::failed ? 1 : 0;
  return failed;
}

}  // namespace hs::campaign
