// SPDX-License-Identifier: MIT
// The one-rank guard of the unresolved stage.
#include "unresolved/coupling/one_rank_guard.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {

void require_one_rank(std::string_view what, MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) return;
  throw hs::common::ConfigError(fmt::format(
      "{}: started on {} MPI ranks, but the unresolved CFD-DEM solver runs on one rank only: its fluid grid and "
      "particles are not distributed yet, so every rank would compute the whole problem. Run it on one rank "
      "(without mpirun, or mpirun -np 1); OpenMP threads (OMP_NUM_THREADS) still use the cores.",
      what, ranks));
}

}  // namespace hs::unresolved
