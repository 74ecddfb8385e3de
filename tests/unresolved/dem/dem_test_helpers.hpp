// SPDX-License-Identifier: MIT
// Shared set-up of the DEM tests: particle parameters of the LIGGGHTS anchor and an open box domain.
#pragma once

#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved::test {

/// The spheres of shared/bench/liggghts/in.rbcpack: d = 7.82 um, rho = 1100, E = 1e5 Pa, nu = 0.45, e = 0.5, mu = 0.3.
inline ParticleParams rbcpack_params() {
  ParticleParams p = default_particle_params();
  p.diameter_m = 7.82e-6;
  p.skin_m = 0.1 * p.diameter_m;
  return p;
}

/// A cube of half-width `half_m` around the origin, periodic or not along every axis.
inline Domain cube(double half_m, bool periodic) {
  return {.box = {.lo = {-half_m, -half_m, -half_m}, .hi = {half_m, half_m, half_m}},
          .periodic = {periodic, periodic, periodic}};
}

}  // namespace hs::unresolved::test
