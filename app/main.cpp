// SPDX-License-Identifier: MIT
// The `hemoscale` command line: parse, dispatch to one subcommand, turn errors into exit codes.
#include <mpi.h>

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "build_info.hpp"
#include "common/errors.hpp"
#include "common/stop_request.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);

  CLI::App cli{"hemoscale: blood flow at the cell level, from one resolved red blood cell to 10^6 unresolved ones."};
  cli.set_version_flag("--version", std::string("hemoscale ") + hs::common::build_info::version + " (" +
                                        hs::common::build_info::git_commit + ")");
  cli.require_subcommand(1);
  hs::app::Action action;
  hs::app::add_run_command(cli, action);
  hs::app::add_bench_command(cli, action);
  hs::app::add_validate_command(cli, action);
  hs::app::add_campaign_command(cli, action);
  hs::app::add_fit_command(cli, action);
  hs::app::add_study_command(cli, action);

  int code = 0;
  try {
    cli.parse(argc, argv);
    code = action ? action() : 0;
  } catch (const CLI::ParseError& e) {
    code = cli.exit(e);
    if (code != 0) code = hs::common::exit_code_config_error;
  } catch (const hs::common::ConfigError& e) {
    if (rank == 0) std::fprintf(stderr, "error: %s\n", e.what());
    code = hs::common::exit_code_config_error;
  } catch (const hs::common::NumericalError& e) {
    if (rank == 0) std::fprintf(stderr, "numerical failure: %s\n", e.what());
    code = hs::common::exit_code_numerical_error;
  } catch (const hs::common::RunInterrupted& e) {
    if (rank == 0) std::fprintf(stderr, "interrupted: %s\n", e.what());
    code = e.exit_code();
  } catch (const std::exception& e) {
    if (rank == 0) std::fprintf(stderr, "internal error: %s\n", e.what());
    code = 1;
  }
  MPI_Finalize();
  return code;
}
