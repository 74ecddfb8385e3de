// SPDX-License-Identifier: MIT
// Global reductions over the ranks of a decomposition.
#include "common/parallel/reductions.hpp"

namespace hs::common {

double global_sum(double local, MPI_Comm comm) {
  double r = 0.0;
  MPI_Allreduce(&local, &r, 1, MPI_DOUBLE, MPI_SUM, comm);
  return r;
}

long global_sum(long local, MPI_Comm comm) {
  long r = 0;
  MPI_Allreduce(&local, &r, 1, MPI_LONG, MPI_SUM, comm);
  return r;
}

double global_max(double local, MPI_Comm comm) {
  double r = 0.0;
  MPI_Allreduce(&local, &r, 1, MPI_DOUBLE, MPI_MAX, comm);
  return r;
}

double global_min(double local, MPI_Comm comm) {
  double r = 0.0;
  MPI_Allreduce(&local, &r, 1, MPI_DOUBLE, MPI_MIN, comm);
  return r;
}

}  // namespace hs::common
