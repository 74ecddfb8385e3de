// SPDX-License-Identifier: MIT
// Velocity Verlet whose half kicks integrate a linear drag beta (u_f - v) exactly (exponential integrator).
#pragma once

#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Half kick of the owned particles over h_s = dt/2 for m dv/dt = beta (u_f - v) + F, with F = force_N() (contacts,
/// walls, hook) + external_force_N(), and F, beta, u_f held constant over the half step, solved exactly:
///   v <- v + g (F + beta (u_f - v)) / m,   g = h (1 - exp(-x)) / x,  x = h beta / m
/// (g = h when beta = 0: plain velocity Verlet). Unconditionally stable in beta: for x >> 1, v -> u_f + F/beta,
/// the terminal velocity, instead of the explicit step's growing oscillation (unresolved-methods.md 8, item 3).
/// Angular velocity likewise with the rotational drag beta_r (Omega_f - w) (ParticleStore::rotational_drag_N_m_s(),
/// I = 0.4 m r^2; beta_r = 0: w += h (T + T_ext) / I as fix nve/sphere). For an RBC sphere in plasma I / beta_r is
/// 0.5 us, below the DEM step: an explicit fluid torque would diverge. The drag part of the impulse, m dv - h F, is added
/// to drag_impulse_N_s() so the coupling can give the fluid exactly the opposite.
void exponential_half_kick(ParticleStore& particles, double h_s);

/// x <- x + dt v for the owned particles.
void drift(ParticleStore& particles, double dt_s);

}  // namespace hs::unresolved
