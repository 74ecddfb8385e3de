// SPDX-License-Identifier: MIT
// Half Verlet neighbour list with skin, built on linked cells, carrying the tangential contact history.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Tangential springs of the contacts alive at a rebuild, keyed by the ids (smaller first) of the two particles.
struct ContactHistory {
  std::vector<std::pair<std::int64_t, std::int64_t>> keys;   // sorted
  std::vector<std::array<double, 3>> shear_m;
};

/// For each owned particle i the candidates j (owned or ghost) with |x_i - x_j| < r_i + r_j + skin and
/// id_j > id_i: every pair once (also across periodic or block faces, where the block owning the smaller id
/// computes it), so forces are applied to both partners (Newton's third law, half list as LIGGGHTS'
/// neigh_half_bin). Rebuilt when an owned particle moved more than skin/2 since the last build.
class NeighborList {
 public:
  explicit NeighborList(double skin_m) : skin_m_(skin_m) {}

  /// The springs of the current contacts (those with a non-zero history), before particles are re-sorted.
  [[nodiscard]] ContactHistory extract_history(const ParticleStore& particles) const;
  /// Builds the list over owned particles and ghosts; `history` restores springs of pairs still listed.
  /// `lo_m`/`hi_m` bound all particles including ghosts (clamped otherwise: correct but slower).
  void build(const ParticleStore& particles, const hs::common::Vec3& lo_m, const hs::common::Vec3& hi_m,
             const ContactHistory& history);
  /// Largest displacement of an owned particle since the last build exceeds skin/2. Throws NumericalError on
  /// a non-finite position.
  [[nodiscard]] bool needs_rebuild(const ParticleStore& particles) const;

  [[nodiscard]] std::size_t n_owned() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  [[nodiscard]] const std::vector<std::uint32_t>& offsets() const { return offsets_; }
  [[nodiscard]] const std::vector<std::uint32_t>& neighbors() const { return neighbors_; }
  [[nodiscard]] std::vector<std::array<double, 3>>& shear_m() { return shear_; }
  /// R* = r_i r_j / (r_i + r_j) and m* = m_i m_j / (m_i + m_j) of each listed pair, fixed between builds.
  [[nodiscard]] const std::vector<std::array<double, 2>>& pair_effective() const { return pair_eff_; }
  [[nodiscard]] std::size_t n_builds() const { return n_builds_; }
  [[nodiscard]] double skin_m() const { return skin_m_; }

 private:
  void restore_history(const ParticleStore& particles, const ContactHistory& history);

  double skin_m_;
  std::vector<std::uint32_t> offsets_;    // CSR: neighbours of i are [offsets_[i], offsets_[i+1])
  std::vector<std::uint32_t> neighbors_;
  std::vector<std::array<double, 3>> shear_;
  std::vector<std::array<double, 2>> pair_eff_;
  std::array<std::vector<double>, 3> x_at_build_;
  std::size_t n_builds_ = 0;
};

/// Order of the owned particles by linked cell (for memory locality of the contact loop).
[[nodiscard]] std::vector<std::size_t> cell_sort_order(const ParticleStore& particles, const Domain& domain,
                                                       double cell_m);

}  // namespace hs::unresolved
