// SPDX-License-Identifier: MIT
// Reads the named openings of a case file ([openings.NAME] sections), with their flow conditions, and checks them
// against the geometry.
#pragma once

#include <vector>

#include "common/config/config_file.hpp"
#include "common/geometry/opening.hpp"
#include "common/geometry/opening_condition.hpp"

namespace hs::common {

/// Each sub-section [openings.NAME] is one opening (names sorted), with keys:
///   kind     = "inlet" | "outlet"
///   centre_m = [x, y, z]    on a face of the domain box, inside the fluid
///   normal   = [nx, ny, nz] dimensionless, normalised here; the outward normal of that face
///   radius_m                the disc's radius, inside the shape's cross-section
/// The fluid's condition keys are read by opening_conditions_from_config (below); the DEM's (hematocrit) by the DEM.
/// Any problem of find_openings_problem is a ConfigError naming file, section, key and value.
[[nodiscard]] std::vector<Opening> openings_from_config(ConfigSection openings, const Shape& shape, const Box3& domain);

/// The openings as above, each with its flow condition for the fluid solver (docs/openings.md):
///   flow_rate_m3_s   inlet only, required: the volume flow rate in (> 0), imposed with a developed profile
///   pressure_Pa      outlet: the pressure on the opening
///   flow_fraction    outlet: its share of the summed inlet flow rates, in (0, 1]
/// An outlet needs exactly one of pressure_Pa and flow_fraction. ConfigError (file, section, key, value, what is
/// allowed) for a missing or contradictory key, a key of the other kind, or a problem of find_openings_problem or
/// find_conditions_problem (fractions that do not add up).
[[nodiscard]] std::vector<OpeningCondition> opening_conditions_from_config(ConfigSection openings, const Shape& shape,
                                                                           const Box3& domain);

}  // namespace hs::common
