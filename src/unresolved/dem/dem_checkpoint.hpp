// SPDX-License-Identifier: MIT
// Binary checkpoints of a DEM block: owned particles with all their columns and the contact springs.
#pragma once

#include <filesystem>

#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {

/// Writes the owned particles (every column, forces included) and the contact history atomically.
void write_dem_checkpoint(const DemSystem& dem, const std::filesystem::path& file);

/// Replaces the particles of `dem` with those of the checkpoint; the next step continues the saved run.
/// A missing, truncated or foreign file throws ConfigError.
void read_dem_checkpoint(DemSystem& dem, const std::filesystem::path& file);

}  // namespace hs::unresolved
