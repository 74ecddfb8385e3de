// SPDX-License-Identifier: MIT
// Reads the named openings of a case file ([openings.NAME] sections) and checks them against the geometry.
#pragma once

#include <vector>

#include "common/config/config_file.hpp"
#include "common/geometry/opening.hpp"

namespace hs::common {

/// Each sub-section [openings.NAME] is one opening (names sorted), with keys:
///   kind     = "inlet" | "outlet"
///   centre_m = [x, y, z]    on a face of the domain box, inside the fluid
///   normal   = [nx, ny, nz] dimensionless, normalised here; the outward normal of that face
///   radius_m                the disc's radius, inside the shape's cross-section
/// Keys for the solvers (flow rate, pressure, hematocrit) live in the same sections and are read by them.
/// Any problem of find_openings_problem is a ConfigError naming file, section, key and value.
[[nodiscard]] std::vector<Opening> openings_from_config(ConfigSection openings, const Shape& shape, const Box3& domain);

}  // namespace hs::common
