// SPDX-License-Identifier: MIT
// Global reductions over the ranks of a decomposition (sums, extrema), the same call at np = 1.
#pragma once

#include <mpi.h>

namespace hs::common {

/// Sum of `local` over all ranks of `comm`.
double global_sum(double local, MPI_Comm comm);
/// Sum of a count over all ranks of `comm`.
long global_sum(long local, MPI_Comm comm);
/// Maximum of `local` over all ranks of `comm`.
double global_max(double local, MPI_Comm comm);
/// Minimum of `local` over all ranks of `comm`.
double global_min(double local, MPI_Comm comm);

}  // namespace hs::common
