// SPDX-License-Identifier: MIT
// Writing the owned particles as VTK PolyData vertices (ParaView: Glyph filter with the radius).
#pragma once

#include <filesystem>

#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// Writes points (m) with id, radius_m, velocity_m_s, angular_velocity_rad_s, force_N (contacts + hook),
/// external_force_N, drag_force_N and lift_force_N (where the coupling set them), deformation_index and
/// inlet_opening (Int32: the index of the opening the particle came in by, -1 if placed at the start).
void write_particles_vtp(const ParticleStore& particles, const std::filesystem::path& file);

}  // namespace hs::unresolved
