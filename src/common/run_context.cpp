// SPDX-License-Identifier: MIT
// The shared opening and closing of every `hemoscale run`.
#include "common/run_context.hpp"

#include <mpi.h>

#include <string>
#include <utility>

#include "common/errors.hpp"
#include "common/peak_memory.hpp"
#include "common/summary_schema.hpp"

namespace hs::common {

RunContext RunContext::start(const CaseRequest& request, const std::string& case_type) {
  request.config->finish();   // every key was read by now: anything left is a typo or unknown
  RunContext ctx;
  ctx.case_type_ = case_type;
  ctx.resume_ = request.resume;
  ctx.quick_ = request.quick;
  ctx.show_progress_ = !request.quiet;
  ctx.start_ = std::chrono::steady_clock::now();
  int mpi_on = 0;
  MPI_Initialized(&mpi_on);   // unit tests may call this without MPI: then one rank
  if (mpi_on) {
    MPI_Comm_rank(MPI_COMM_WORLD, &ctx.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ctx.ranks_);
  }

  // Rank 0 claims the folder; the others learn its path (a failure on rank 0 is broadcast as an empty path).
  std::string path;
  std::string error;
  if (ctx.rank_ == 0) {
    try {
      if (request.resume) {
        path = RunFolder::open_existing(*request.output_dir).path().string();
      } else if (request.output_dir) {
        path = RunFolder::create_exact(*request.output_dir).path().string();
      } else {
        path = RunFolder::create_new(request.case_dir / "runs").path().string();
      }
    } catch (const ConfigError& e) {
      error = e.what();
    }
  }
  int length = static_cast<int>(error.empty() ? path.size() : 0);
  if (mpi_on) MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (length == 0) throw ConfigError(ctx.rank_ == 0 ? error : "run folder could not be created (see rank 0)");
  path.resize(static_cast<std::size_t>(length));
  if (mpi_on) MPI_Bcast(path.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);

  ctx.folder_ = std::make_unique<RunFolder>(RunFolder::open_existing(path));
  ctx.log_ = std::make_unique<Log>(ctx.rank_);
  ctx.log_->open_file(ctx.folder_->file("log.txt"));
  // Every line of a --quick run says so: its numbers come from a coarse, short smoke version of the case.
  ctx.log_->set_quiet(request.quiet);
  if (request.quick) ctx.log_->set_prefix("[--quick] ");
  if (ctx.rank_ == 0) {
    request.config->write_resolved(ctx.folder_->file("case.resolved.toml"), request.quick, request.resume);
  }
  ctx.log_->info("{} {}{}: {}", request.resume ? "resuming" : "running", case_type,
                 request.quick ? " (--quick: the coarse CI version, a smoke test, not a result)" : "",
                 ctx.folder_->path().string());
  return ctx;
}

double RunContext::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

nlohmann::json RunContext::write_summary(nlohmann::json blocks, const CheckList& checks) const {
  // Every rank writes its summary (the distributed cases call this on all of them): the job's memory is the sum.
  double memory = peak_memory_gib();
  if (ranks_ > 1) MPI_Allreduce(MPI_IN_PLACE, &memory, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  const nlohmann::json summary =
      assemble_summary(std::move(blocks), checks,
                       {.case_type = case_type_, .quick = quick_, .mpi_ranks = ranks_, .wall_time_s = wall_seconds(),
                        .peak_memory_GiB = memory, .provenance = provenance()});
  if (rank_ == 0) write_json(folder_->file("summary.json"), summary);
  return summary;
}

}  // namespace hs::common
