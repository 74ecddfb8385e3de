// SPDX-License-Identifier: MIT
// Every rank's owned particles on every rank, by id: how the tests on z-slabs compare a distributed run with one rank
// holding every particle.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "common/vec3.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::test {

/// id -> {position, velocity} of the owned particles of every rank of `comm` (an id owned twice: the later rank's).
inline std::map<std::int64_t, std::array<hs::common::Vec3, 2>> gathered_particles(const hs::unresolved::ParticleStore& ps,
                                                                                 MPI_Comm comm) {
  std::vector<double> mine;
  for (std::size_t i = 0; i < ps.n_owned(); ++i) {
    mine.insert(mine.end(), {static_cast<double>(ps.id()[i]), ps.position_m()[0][i], ps.position_m()[1][i],
                             ps.position_m()[2][i], ps.velocity_m_s()[0][i], ps.velocity_m_s()[1][i],
                             ps.velocity_m_s()[2][i]});
  }
  int size = 0;
  MPI_Comm_size(comm, &size);
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size));
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::vector<int> displs(static_cast<std::size_t>(size), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(displs.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm);
  std::map<std::int64_t, std::array<hs::common::Vec3, 2>> out;
  for (std::size_t at = 0; at + 7 <= all.size(); at += 7) {
    out[static_cast<std::int64_t>(all[at])] = {hs::common::Vec3{all[at + 1], all[at + 2], all[at + 3]},
                                               hs::common::Vec3{all[at + 4], all[at + 5], all[at + 6]}};
  }
  return out;
}

}  // namespace hs::test
