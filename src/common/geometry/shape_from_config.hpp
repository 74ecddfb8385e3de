// SPDX-License-Identifier: MIT
// Builds the fluid region from a case file's [geometry] section: the same keys in both stages.
#pragma once

#include <memory>

#include "common/config/config_file.hpp"
#include "common/geometry/shape.hpp"

namespace hs::common {

/// Convention for every built-in shape: the main flow runs along +x from x = 0, centred on the x axis
/// (y = z = 0). Keys (SI units, in the [geometry] section):
///   shape = "tube":             radius_m, length_m
///   shape = "stenosed-tube":    radius_m, length_m, throat_radius_m, constriction_length_m, [constriction_centre_m = length/2]
///   shape = "stenosed-channel": height_m, width_m (z extent), length_m, throat_height_m, constriction_length_m,
///                               [constriction_centre_m = length/2]
///   shape = "bifurcation":      parent_diameter_m, parent_length_m, daughter_diameters_m = [d0, d1],
///                               daughter_lengths_m = [l0, l1], daughter_angles_deg = [a0, a1]  (junction at x = parent_length_m)
///   shape = "box":              size_m = [lx, ly, lz]  (from (0, -ly/2, -lz/2))
///   shape = "stl":              file (relative to the case file), [scale_to_m = 1]
/// and for any shape [axis = "x"]: "z" turns it so that its +x runs along +z (TurnedToZ; its +z along -x), as the
/// distributed CFD-DEM needs (its inlets face along z). Every invalid combination is a ConfigError naming the key.
std::shared_ptr<const Shape> shape_from_config(ConfigSection geometry);

}  // namespace hs::common
