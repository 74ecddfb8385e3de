// SPDX-License-Identifier: MIT
// Particle-particle contact forces over the half neighbour list, threaded with per-thread force buffers.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/neighbor_list.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Computes Hertz/history forces and torques of all listed pairs and ASSIGNS them to force_N()/torque_Nm()
/// of owned particles and ghosts (call first in a force evaluation). With several OpenMP threads each thread
/// takes a contiguous range of i (balanced by pair count) and writes into its own buffer over the index range
/// it touches; the buffers are then summed. Pair forces are exactly antisymmetric, so total momentum is
/// conserved to round-off.
class PairContacts {
 public:
  explicit PairContacts(const HertzContactLaw& law) : law_(law) {}

  /// Returns the number of pairs in contact.
  std::size_t compute(ParticleStore& particles, NeighborList& list, double dt_s);

 private:
  struct ThreadRange {
    std::size_t i_lo, i_hi;          // owned particles handled
    std::size_t touch_lo, touch_hi;  // owned indices written (i and j)
    std::size_t ghost_lo, ghost_hi;  // ghost indices written (empty when lo == hi)
    [[nodiscard]] bool touches(std::size_t k) const {
      return (k >= touch_lo && k < touch_hi) || (k >= ghost_lo && k < ghost_hi);
    }
  };
  void plan(const ParticleStore& particles, const NeighborList& list, int n_threads);
  std::size_t compute_range(ParticleStore& p, NeighborList& list, double dt_s, std::size_t i_lo, std::size_t i_hi,
                            std::array<double*, 6> out) const;

  HertzContactLaw law_;
  std::vector<ThreadRange> ranges_;
  std::vector<std::array<std::vector<double>, 6>> buffers_;
  std::size_t planned_build_ = static_cast<std::size_t>(-1);
};

}  // namespace hs::unresolved
