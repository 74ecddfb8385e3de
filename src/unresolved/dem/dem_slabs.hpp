// SPDX-License-Identifier: MIT
// The DEM on z-slabs (issue #28 step 3): which rank owns a particle, and the particle traffic between neighbouring
// slabs (migration, ghost copies, their refresh and their forces' way back).
#pragma once

#include <mpi.h>

#include <array>
#include <cstddef>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"
#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/neighbor_list.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Rank k owns the particles whose centre lies in its slab [lo_m, hi_m) of the box along z: the planes of the FVM's
/// z-slabs (`slabs`, ranks along z only) times the cell size, so a particle's owner is the owner of its centre's
/// cell. Particles move to the neighbouring slab at neighbour-list rebuilds (migrate), with their contact springs;
/// the neighbours' particles within the cut-off of a slab's faces are copied in as ghosts (exchange_ghosts), refreshed
/// every step (update_ghosts), and the contact forces computed on them go back to their owners (fold_ghost_forces).
/// A pair is computed once, by the rank owning its smaller id (NeighborList's rule), as on one rank. Every call is
/// collective over the slabs' communicator. A slab must be at least a cut-off thick, so ghosts come from the two
/// neighbours only and a particle crosses at most one face between rebuilds (it moves less than half a skin).
class DemSlabs {
 public:
  /// The decomposition must outlive this object.
  DemSlabs(const hs::common::CartesianDecomposition& slabs, const Domain& domain, double dx_m);

  [[nodiscard]] MPI_Comm comm() const { return slabs_.comm(); }
  [[nodiscard]] int rank() const { return slabs_.rank(); }
  [[nodiscard]] double lo_m() const { return lo_m_; }
  [[nodiscard]] double hi_m() const { return hi_m_; }
  /// The domain a block integrates: the box cut to this slab along z, which is not periodic within a block.
  [[nodiscard]] const Domain& block_domain() const { return block_; }
  /// ConfigError on every rank when a slab is thinner than `cutoff_m` (collective).
  void check_thickness(double cutoff_m) const;

  /// Sends each owned particle whose centre left the slab to the neighbour that holds it now (across a periodic
  /// seam wrapped into the box) with every column and the springs of its pairs it computes (those with a larger
  /// id). Requires no ghosts. Returns the springs now computed here: `history` less what left, plus what came.
  ContactHistory migrate(ParticleStore& particles, const ContactHistory& history) const;
  /// Appends as remote ghosts the neighbours' particles (owned and their periodic images) within `width_m` of this
  /// slab's faces, with their coupling inputs (GhostCoupling), and remembers who sent what for the
  /// updates below.
  void exchange_ghosts(ParticleStore& particles, double width_m);
  /// Refreshes the remote ghosts' position, velocity and angular velocity (after the local periodic images).
  void update_ghosts(ParticleStore& particles) const;
  /// Sends the forces and torques on remote ghosts to their owners, adds them there and clears them here (before
  /// ParticleStore::fold_ghost_forces, which takes them on to an owned particle when the owner was an image).
  void fold_ghost_forces(ParticleStore& particles) const;

  /// The same for one value per particle (owned and ghosts, in the store's order): each remote ghost's value is
  /// added to the particle it copies, on its rank, and cleared here.
  void fold_values(std::vector<double>& value) const;

  /// The coupling's columns (one value per row each, e.g. the drag coefficient, the lift's components): sends the
  /// owners' values to their remote ghosts (a periodic image sends the values of the particle it copies).
  void update_ghost_columns(const ParticleStore& particles, const std::vector<ParticleStore::Column*>& columns) const;
  /// The reverse: adds each remote ghost's values to the particle it copies on its owner's rank (to that particle's
  /// coupling row when the owner sent an image) and clears them here. A value computed by exactly one copy, the others
  /// holding zero, arrives unchanged: x + 0 is x.
  void fold_ghost_columns(const ParticleStore& particles, const std::vector<ParticleStore::Column*>& columns) const;

  /// Whether any rank's flag is set (rebuild decisions).
  [[nodiscard]] bool any(bool mine) const;
  [[nodiscard]] double max(double mine) const;
  [[nodiscard]] double min(double mine) const;

 private:
  /// The neighbour on `side` (0 below, 1 above) and the shift along z a particle sent there takes (+-L across a
  /// periodic seam, else 0); MPI_PROC_NULL at a wall.
  [[nodiscard]] int neighbour(int side) const { return slabs_.neighbour(2, side); }
  [[nodiscard]] double shift_to(int side) const;
  /// Sends out[s] to the neighbour on side s and receives in[s] from it, both sides at once (collective with the
  /// neighbours). `sizes_known`: in[] already has the sizes to receive; otherwise they are exchanged first.
  void exchange(const std::array<std::vector<double>, 2>& out, std::array<std::vector<double>, 2>& in, bool sizes_known,
                int tag) const;

  const hs::common::CartesianDecomposition& slabs_;
  Domain block_;
  double lo_m_ = 0.0;
  double hi_m_ = 0.0;
  double length_m_ = 0.0;
  bool periodic_ = false;
  std::array<std::vector<std::size_t>, 2> sent_;   // per side: indices copied to that neighbour as its ghosts
  std::array<std::size_t, 2> received_first_{};    // per side: the first of the ghosts that neighbour sent here
  std::array<std::size_t, 2> received_count_{};
};

}  // namespace hs::unresolved
