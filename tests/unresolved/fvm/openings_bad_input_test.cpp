// SPDX-License-Identifier: MIT
// Openings the FVM grid refuses with a ConfigError (exit 2): one that does not cut the geometry's wall, one on a side
// that is not a wall, one too small to hold a face node, and conditions that do not add up. Also which face nodes an
// opening holds (node centre within the disc and in the fluid).
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "common/geometry/opening_condition.hpp"
#include "common/geometry/tube.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace {

using hs::common::ConfigError;
using hs::common::Opening;
using hs::common::OpeningKind;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::NodeKind;
using hs::unresolved::SideType;

constexpr double kRadius = 10e-6;
constexpr double kLength = 40e-6;
constexpr double kDx = 2e-6;

const hs::common::Tube& tube() {
  static const hs::common::Tube t({.start_m = {0, 0, 0}, .end_m = {kLength, 0, 0}, .radius_m = kRadius});
  return t;
}

Opening inlet() {
  return {.name = "in", .kind = OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {-1, 0, 0}, .radius_m = kRadius};
}

Opening outlet(double y_m = 0.0, double radius_m = kRadius) {
  return {.name = "out", .kind = OpeningKind::outlet, .centre_m = {kLength, y_m, 0}, .normal = {1, 0, 0},
          .radius_m = radius_m};
}

FvmGridSpec spec(double half_width_m = kRadius) {
  return {.box_m = {{0, -half_width_m, -half_width_m}, {kLength, half_width_m, half_width_m}},
          .dx_m = kDx,
          .sides = {}};
}

/// The ConfigError message of building the grid, or "" when it builds.
std::string error_of(const FvmGridSpec& s) {
  try {
    const FvmGrid grid(tube(), s);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; }

}  // namespace

TEST(FvmOpenings, AnOpeningThatDoesNotCutTheWallIsAConfigError) {
  FvmGridSpec s = spec(2 * kRadius);   // a box wider than the tube: its x+ face is wall material around the tube
  s.openings = {hs::common::flow_rate_inlet(inlet(), 1e-13), hs::common::pressure_outlet(outlet(15e-6, 2e-6), 0.0)};
  const std::string msg = error_of(s);
  EXPECT_TRUE(has(msg, "opening 'out': centre_m: is not inside the fluid")) << msg;
  EXPECT_TRUE(has(msg, "does not cut the geometry's wall")) << msg;
}

TEST(FvmOpenings, AnOpeningOnASideThatIsNotAWallIsAConfigError) {
  FvmGridSpec s = spec();
  s.openings = {hs::common::flow_rate_inlet(inlet(), 1e-13), hs::common::pressure_outlet(outlet(), 0.0)};
  s.sides[1].type = SideType::pressure_outlet;   // the side and the opening would both say what x+ is
  std::string msg = error_of(s);
  EXPECT_TRUE(has(msg, "opening 'out' lies on the x+ side of the box, whose condition is pressure_outlet")) << msg;
  s.sides[0].type = SideType::periodic;
  s.sides[1].type = SideType::periodic;
  msg = error_of(s);
  EXPECT_TRUE(has(msg, "opening 'in' lies on the x- side of the box, whose condition is periodic")) << msg;
}

TEST(FvmOpenings, AnOpeningThatHoldsNoFaceNodeIsAConfigError) {
  // Face centres sit at odd micrometres (y, z = +-1, +-3, ...): a disc of 0.9 um around the axis holds none.
  FvmGridSpec s = spec();
  s.openings = {hs::common::flow_rate_inlet(inlet(), 1e-13), hs::common::pressure_outlet(outlet(0.0, 0.9e-6), 0.0)};
  const std::string msg = error_of(s);
  EXPECT_TRUE(has(msg, "opening 'out' (radius_m = 9e-07) holds no face node of the grid (dx_m = 2e-06)")) << msg;
}

TEST(FvmOpenings, ConditionsThatDoNotAddUpAreAConfigError) {
  FvmGridSpec s = spec();
  s.openings = {hs::common::flow_rate_inlet(inlet(), 1e-13), hs::common::flow_fraction_outlet(outlet(), 0.5)};
  EXPECT_TRUE(has(error_of(s), "opening 'out': flow_fraction: the flow fractions of the outlets sum to 0.5"));
  s.openings = {hs::common::pressure_outlet(inlet(), 0.0), hs::common::pressure_outlet(outlet(), 0.0)};
  EXPECT_TRUE(has(error_of(s), "opening 'in': pressure_Pa: is for an outlet"));
}

TEST(FvmOpenings, FaceNodesInsideTheDiscBelongToTheOpening) {
  // A half-radius outlet on the tube's end: the face nodes within 5 um of the axis are open (active), the rest of
  // the tube's cross-section on that face is wall (fixed at 0); the inlet's nodes are fixed at its profile.
  FvmGridSpec s = spec();
  s.openings = {hs::common::flow_rate_inlet(inlet(), 1e-13),
                hs::common::pressure_outlet(outlet(0.0, 0.5 * kRadius), 0.0)};
  const FvmGrid grid(tube(), s);
  const int n = grid.cells()[0];
  int open = 0;
  int wall = 0;
  for (int k = 0; k < grid.node_count(0, 2); ++k) {
    for (int j = 0; j < grid.node_count(0, 1); ++j) {
      const auto p = grid.node_position_m(0, n, j, k);
      if (grid.kind(0, n, j, k) == NodeKind::solid) continue;
      const bool inside = p.y * p.y + p.z * p.z <= 0.25 * kRadius * kRadius;
      EXPECT_EQ(grid.kind(0, n, j, k), inside ? NodeKind::active : NodeKind::fixed) << "y = " << p.y << ", z = " << p.z;
      (inside ? open : wall) += 1;
      if (grid.kind(0, 0, j, k) == NodeKind::fixed) {
        EXPECT_GT(grid.fixed_values(0)(0, j, k), 0.0);   // the inlet: inflow along +x
      }
    }
  }
  // Face centres (odd micrometres) inside the tube: 20 per quadrant, 80 in all; within 5 um of the axis: (1, 1),
  // (1, 3), (3, 1), (3, 3) um per quadrant, 16 in all. The other 64 are wall.
  EXPECT_EQ(open, 16);
  EXPECT_EQ(wall, 64);
  EXPECT_EQ(grid.opening_nodes(1).nodes.size(), 16u);
  EXPECT_EQ(grid.opening_nodes(0).nodes.size(), 80u);
}
