// SPDX-License-Identifier: MIT
// Periodic boundaries through ghost particles: wrapping owned particles and making their periodic images.
#pragma once

#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Moves every owned particle into [lo, hi) along each periodic axis.
void wrap_periodic(ParticleStore& particles, const Domain& domain);

/// Replaces the ghosts with the periodic images of all particles lying within `width_m` of a periodic face,
/// axis after axis, so edge and corner images exist too (as LAMMPS builds its periodic halo).
/// pre: owned particles wrapped; every periodic length >= 2 width_m (checked by DemSystem).
void build_periodic_ghosts(ParticleStore& particles, const Domain& domain, double width_m);

}  // namespace hs::unresolved
