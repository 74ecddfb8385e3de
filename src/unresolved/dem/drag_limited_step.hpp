// SPDX-License-Identifier: MIT
// The DEM step of an overdamped suspension: set by how fast the contacts relax against the fluid drag, not by the
// contacts' elastic oscillation (docs/cfd-dem.md "The DEM sub-step").
#pragma once

#include "unresolved/dem/hertz_contact_law.hpp"
#include "unresolved/dem/neighbor_list.hpp"
#include "unresolved/dem/particle_store.hpp"
#include "unresolved/dem/wall_contacts.hpp"

namespace hs::unresolved {

class DemSlabs;

/// dt_DEM lambda <= drag_limited_step_fraction, lambda the bound below. In the overdamped limit the exponential
/// Verlet step (exponential_verlet.hpp) is explicit Euler of x' = M F(x) (M the drag mobility): a contact mode of
/// rate lambda relaxes by 1 - dt lambda per step, monotone for dt lambda <= 1, stable for < 2. 0.5 keeps half the
/// monotone range and leaves the stiffness room to grow 4x within a CFD step before the step goes unstable.
inline constexpr double drag_limited_step_fraction = 0.5;
/// The contact dashpot is explicit: in the overdamped limit it feeds back gamma M per step. The 1-D relative
/// contact mode under the exponential Verlet step stays stable at dt lambda = 1 (twice the fraction above) for
/// gamma M up to 0.3 (measured on the 2x2 linear map, docs/cfd-dem.md); above it the rule does not apply.
inline constexpr double drag_limited_max_damping_number = 0.3;
/// The analysis needs the contact modes overdamped: lambda tau_p <= 1/4 (damping ratio >= 1), tau_p the largest
/// inertial relaxation time m / beta or I / beta_r of a particle.
inline constexpr double drag_limited_max_rate_times_tau = 0.25;

/// The drag-limited DEM step of the particles as they are, or why it does not apply.
struct DragLimitedStep {
  bool applies = false;             // false: keep the inertial step (0.1 min(t_Rayleigh, t_Hertz))
  double time_step_s = 0.0;         // drag_limited_step_fraction / lambda (infinite with no contact to come)
  double rate_bound_1_s = 0.0;      // lambda
  double damping_number = 0.0;      // max gamma M over the contacts
  double inertial_time_s = 0.0;     // max m / beta, I / beta_r
  const char* reason = "";          // why it does not apply
};

/// lambda bounds the largest relaxation rate of the overdamped contact network x' = M F(x) (Gershgorin on K M):
///   lambda = max_i sum over the contacts c of i of max(k_n (M_n,i + M_n,j), k_t (M_t,i + M_t,j)),
/// k_n = 2 Y* a and k_t = 8 G* a the Hertz and Mindlin stiffnesses at a = sqrt(R* delta) (hertz_kernel.hpp),
/// M_n = 1 / beta and M_t = 1 / beta + r^2 / beta_r a particle's normal and tangential (contact point) mobility,
/// a wall's mobility zero. delta is the larger of the current overlap and the Hertz overlap under the force the
/// fluid can press the pair together with, |(w_i - w_j) . n| / (M_n,i + M_n,j) with w = u_f + F_ext / beta
/// the free drift (pairs of the neighbour list and the wall candidates, so contacts about to form count too).
/// Needs every owned particle to have beta > 0 and beta_r > 0 (drag_used()); `walls` may be null. With `slabs`
/// (collective): over every rank's particles, the rates of contacts with another rank's particles summed on both
/// sides, after DemSlabs::exchange_ghosts (a fresh rebuild) brought the ghosts' drag.
[[nodiscard]] DragLimitedStep drag_limited_step(const ParticleStore& particles, const NeighborList& list,
                                                const HertzContactLaw& law, const WallContacts* walls,
                                                const DemSlabs* slabs = nullptr);

}  // namespace hs::unresolved
