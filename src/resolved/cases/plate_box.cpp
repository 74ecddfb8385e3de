// SPDX-License-Identifier: MIT
// Reading and checking the box between two plates.
#include "resolved/cases/plate_box.hpp"

#include <initializer_list>
#include <utility>

#include <fmt/format.h>

#include "common/fluid_properties.hpp"

namespace hs::resolved {

hs::common::ConfigSection read_plate_box(hs::common::ConfigSection root, PlateBox& box) {
  auto geometry = root.section("geometry");
  box.gap_m = geometry.positive("gap_m");
  box.length_m = geometry.positive("length_m");
  box.width_m = geometry.positive("width_m");
  const common::FluidProperties fluid = common::parse_fluid(root.section("fluid"));
  box.density_kg_m3 = fluid.density_kg_m3;
  box.kinematic_viscosity_m2_s = fluid.kinematic_viscosity_m2_s;
  return geometry;
}

void check_plate_box_span(const hs::common::ConfigSection& geometry, const PlateBox& box, double dx_m) {
  for (const auto& [key, value] : std::initializer_list<std::pair<const char*, double>>{
           {"gap_m", box.gap_m}, {"length_m", box.length_m}, {"width_m", box.width_m}}) {
    if (value < 10.0 * dx_m) geometry.fail(key, fmt::format("must span at least 10 dx_m = {:g} m", 10.0 * dx_m));
  }
}

}  // namespace hs::resolved
