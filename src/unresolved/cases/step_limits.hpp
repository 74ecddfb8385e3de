// SPDX-License-Identifier: MIT
// The time-step limits every CFD-DEM case checks when it reads its [numerics]: Courant and the DEM step.
#pragma once

#include <string_view>

#include "common/config/config_file.hpp"
#include "unresolved/dem/particle_params.hpp"

namespace hs::unresolved {

/// ConfigError on [numerics] dt_s when speed_m_s dt / dx > 1 (CFDEM keeps Co < 1, methods note sec. 0); `where`
/// names the speed ("the inlet's centreline speed").
void check_courant(hs::common::ConfigSection& numerics, double speed_m_s, double dt_s, double dx_m, std::string_view where);

/// ConfigError on [numerics] n_coupling when the DEM step dt_s / n_coupling exceeds 0.1 min(t_Rayleigh, t_Hertz) of the
/// particles (hertz_contact_law.hpp), with the smallest n_coupling that would do.
void check_dem_step(hs::common::ConfigSection& numerics, const ParticleParams& particles, double dt_s, int n_coupling);

}  // namespace hs::unresolved
