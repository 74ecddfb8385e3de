// SPDX-License-Identifier: MIT
// The box between two plates that the plate cases (`shear`, `migration`) and `shear-suspension` share: its extents
// ([geometry]) and the fluid in it ([fluid]), read and checked the same way for each.
#pragma once

#include "common/config/config_file.hpp"

namespace hs::resolved {

/// Walls at y = 0 and y = H; periodic along x (the flow) and z (the vorticity direction).
struct PlateBox {
  // [geometry]
  double gap_m = 0.0;      // H
  double length_m = 0.0;   // periodic box along x
  double width_m = 0.0;    // periodic box along z
  // [fluid]
  double density_kg_m3 = 0.0;
  double kinematic_viscosity_m2_s = 0.0;
};

/// Reads [geometry] gap_m, length_m, width_m and [fluid] into `box`; returns [geometry] for check_plate_box_span.
hs::common::ConfigSection read_plate_box(hs::common::ConfigSection root, PlateBox& box);

/// Each extent spans at least 10 lattice cells of `dx_m`, or a failure on [geometry] naming the key.
void check_plate_box_span(const hs::common::ConfigSection& geometry, const PlateBox& box, double dx_m);

}  // namespace hs::resolved
