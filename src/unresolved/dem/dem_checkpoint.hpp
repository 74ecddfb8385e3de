// SPDX-License-Identifier: MIT
// Binary checkpoints of a DEM block: owned particles with all their columns and the contact springs.
#pragma once

#include <filesystem>
#include <string>

#include "common/io/checkpoint.hpp"
#include "unresolved/dem/dem_system.hpp"

namespace hs::unresolved {

/// Writes the owned particles (every column, forces included) and the contact history atomically.
void write_dem_checkpoint(const DemSystem& dem, const std::filesystem::path& file);

/// Replaces the particles of `dem` with those of the checkpoint; the next step continues the saved run.
/// A missing, truncated or foreign file throws ConfigError.
void read_dem_checkpoint(DemSystem& dem, const std::filesystem::path& file);

/// The same state as named arrays of a common::Checkpoint (names start with `prefix`), for cases that keep the
/// fluid, the particles and the coupling in one atomically replaced restart file.
void write_dem_state(const DemSystem& dem, hs::common::Checkpoint& cp, const std::string& prefix);
/// Restores write_dem_state() like read_dem_checkpoint(); ConfigError when an array is missing or inconsistent.
void read_dem_state(DemSystem& dem, const hs::common::Checkpoint& cp, const std::string& prefix);

}  // namespace hs::unresolved
