// SPDX-License-Identifier: MIT
// Builds the fluid region from a case file's [geometry] section.
#include "common/geometry/shape_from_config.hpp"

#include <fmt/format.h>

#include <utility>

#include "common/geometry/bifurcation.hpp"
#include "common/geometry/box_shape.hpp"
#include "common/geometry/stenosed_channel.hpp"
#include "common/geometry/stenosed_tube.hpp"
#include "common/geometry/stl_shape.hpp"
#include "common/geometry/tube.hpp"
#include "common/geometry/turned_shape.hpp"

namespace hs::common {
namespace {

std::shared_ptr<const Shape> stenosed_tube(ConfigSection& g) {
  const double radius = g.positive("radius_m");
  const double length = g.positive("length_m");
  const double throat = g.positive("throat_radius_m");
  if (throat > radius) g.fail("throat_radius_m", fmt::format("must not exceed radius_m = {}", radius));
  const double c_len = g.positive("constriction_length_m");
  const double centre = g.number_in_or("constriction_centre_m", 0.0, length, 0.5 * length);
  return std::make_shared<StenosedTube>(StenosedTubeSpec{.start_m = {0, 0, 0}, .end_m = {length, 0, 0}, .radius_m = radius,
                                                         .throat_radius_m = throat, .constriction_length_m = c_len,
                                                         .constriction_centre_m = centre});
}

std::shared_ptr<const Shape> stenosed_channel(ConfigSection& g) {
  const double height = g.positive("height_m");
  const double width = g.positive("width_m");
  const double length = g.positive("length_m");
  const double throat = g.positive("throat_height_m");
  if (throat > height) g.fail("throat_height_m", fmt::format("must not exceed height_m = {}", height));
  const double c_len = g.positive("constriction_length_m");
  const double centre = g.number_in_or("constriction_centre_m", 0.0, length, 0.5 * length);
  return std::make_shared<StenosedChannel>(StenosedChannelSpec{.x_start_m = 0, .x_end_m = length, .centre_y_m = 0,
                                                               .height_m = height, .throat_height_m = throat,
                                                               .constriction_length_m = c_len,
                                                               .constriction_centre_x_m = centre, .z_lo_m = -0.5 * width,
                                                               .z_hi_m = 0.5 * width});
}

std::shared_ptr<const Shape> bifurcation(ConfigSection& g) {
  const double d_parent = g.positive("parent_diameter_m");
  const double l_parent = g.positive("parent_length_m");
  const auto d = g.numbers_in("daughter_diameters_m", 1e-300, 1e300, 2);
  const auto l = g.numbers_in("daughter_lengths_m", 1e-300, 1e300, 2);
  const auto a = g.numbers_in("daughter_angles_deg", -179.0, 179.0, 2);
  if (d.size() != 2 || l.size() != 2 || a.size() != 2) g.fail("daughter_diameters_m", "each daughter list must have exactly 2 values");
  for (std::size_t i = 0; i < 2; ++i) {
    if (l[i] <= 0.5 * d[i]) g.fail("daughter_lengths_m", "each daughter must be longer than its radius");
  }
  if (l_parent <= 0.5 * d_parent) g.fail("parent_length_m", "must be longer than the parent radius");
  return std::make_shared<Bifurcation>(BifurcationSpec{.junction_m = {l_parent, 0, 0}, .parent_radius_m = 0.5 * d_parent,
                                                       .parent_length_m = l_parent,
                                                       .daughter_radius_m = {0.5 * d[0], 0.5 * d[1]},
                                                       .daughter_length_m = {l[0], l[1]},
                                                       .daughter_angle_deg = {a[0], a[1]}});
}

std::shared_ptr<const Shape> shape_along_x(ConfigSection g) {
  const std::string shape =
      g.one_of("shape", {"tube", "stenosed-tube", "stenosed-channel", "bifurcation", "box", "stl"});
  if (shape == "tube") {
    const double radius = g.positive("radius_m");
    const double length = g.positive("length_m");
    return std::make_shared<Tube>(TubeSpec{.start_m = {0, 0, 0}, .end_m = {length, 0, 0}, .radius_m = radius});
  }
  if (shape == "stenosed-tube") return stenosed_tube(g);
  if (shape == "stenosed-channel") return stenosed_channel(g);
  if (shape == "bifurcation") return bifurcation(g);
  if (shape == "box") {
    const auto s = g.numbers_in("size_m", 1e-300, 1e300, 3);
    if (s.size() != 3) g.fail("size_m", "must have exactly 3 values [lx, ly, lz]");
    return std::make_shared<BoxShape>(Box3{{0, -0.5 * s[1], -0.5 * s[2]}, {s[0], 0.5 * s[1], 0.5 * s[2]}});
  }
  const auto file = g.file_path("file");
  const double scale = g.positive_or("scale_to_m", 1.0);
  return StlShape::load(file, scale);
}

}  // namespace

std::shared_ptr<const Shape> shape_from_config(ConfigSection g) {
  std::shared_ptr<const Shape> shape = shape_along_x(g);
  if (g.one_of_or("axis", {"x", "z"}, "x") == "z") shape = std::make_shared<TurnedToZ>(std::move(shape));
  return shape;
}

}  // namespace hs::common
