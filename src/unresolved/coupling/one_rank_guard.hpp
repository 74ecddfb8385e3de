// SPDX-License-Identifier: MIT
// The unresolved stage runs on one MPI rank until its FVM grid and DEM particles are decomposed (issue 21).
#pragma once

#include <mpi.h>

#include <string_view>

namespace hs::unresolved {

/// Throws hs::common::ConfigError (exit code 2) when `comm` has more than one rank: the FVM grid, its hypre
/// system and the DEM are not decomposed yet, so every rank would run the whole problem (slower than one rank,
/// with a summary claiming mpi_ranks > 1). `what` names the run in the message ("tube-pries", "validate pries").
/// Call it first, before any output is written. pre: MPI is initialised.
void require_one_rank(std::string_view what, MPI_Comm comm = MPI_COMM_WORLD);

}  // namespace hs::unresolved
