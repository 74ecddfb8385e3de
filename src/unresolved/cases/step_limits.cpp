// SPDX-License-Identifier: MIT
#include "unresolved/cases/step_limits.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "unresolved/dem/hertz_contact_law.hpp"

namespace hs::unresolved {

void check_courant(hs::common::ConfigSection& numerics, double speed_m_s, double dt_s, double dx_m, std::string_view where) {
  if (speed_m_s * dt_s / dx_m > 1.0) {
    numerics.fail("dt_s", fmt::format("gives a Courant number {:.3g} > 1 at {} {:.4g} m/s; use dt_s <= {:.4g}",
                                      speed_m_s * dt_s / dx_m, where, speed_m_s, dx_m / speed_m_s));
  }
}

void check_dem_step(hs::common::ConfigSection& numerics, const ParticleParams& particles, double dt_s, int n_coupling) {
  const double dt_dem = dt_s / n_coupling;
  const double limit = 0.1 * std::min(rayleigh_time_s(particles), hertz_time_s(particles, particles.max_impact_velocity_m_s));
  if (dt_dem > limit) {
    numerics.fail("n_coupling", fmt::format("gives a DEM step dt_s / n_coupling = {:.4g} s > 0.1 min(t_Rayleigh, t_Hertz) = "
                                            "{:.4g} s; use n_coupling >= {}", dt_dem, limit, static_cast<long>(std::ceil(dt_s / limit))));
  }
}

}  // namespace hs::unresolved
