// SPDX-License-Identifier: MIT
// The bifurcation study's settings and geometry.
#include "unresolved/cases/bifurcation_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "common/geometry/bifurcation.hpp"

namespace hs::unresolved {

using hs::common::Vec3;

int BifurcationStudySpec::branch_of(const Vec3& x) const {
  const Vec3 rel = x - junction_m;
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int b = 0; b < 3; ++b) {
    const Vec3& d = branches[static_cast<std::size_t>(b)].direction;
    const double t = std::max(0.0, dot(rel, d));
    const double dist = norm(rel - t * d);
    if (dist < best_d) {
      best_d = dist;
      best = b;
    }
  }
  return best;
}

std::optional<double> BifurcationStudySpec::cut_coordinate(int b, const Vec3& x) const {
  const StudyBranch& br = branches[static_cast<std::size_t>(b)];
  const Vec3 rel = x - junction_m;
  if (std::abs(dot(rel, br.direction) - cut_distance_m) > 0.5 * cut_thickness_m) return std::nullopt;
  const double s = dot(rel, br.across);
  if (std::abs(s) > br.radius_m) return std::nullopt;
  return (s + br.radius_m) / (2.0 * br.radius_m);
}

std::vector<double> BifurcationStudySpec::cut_bin_fluid_m3(int b) const {
  const double r = branches[static_cast<std::size_t>(b)].radius_m;
  std::vector<double> v = disc_strip_fractions(profile_bins);
  for (double& f : v) f *= std::numbers::pi * r * r * cut_thickness_m;
  return v;
}

std::vector<double> disc_strip_fractions(int bins) {
  const auto left_of = [](double x) {   // share of the unit disc left of x in [-1, 1]
    return (x * std::sqrt(std::max(0.0, 1.0 - x * x)) + std::asin(x) + 0.5 * std::numbers::pi) / std::numbers::pi;
  };
  std::vector<double> f(static_cast<std::size_t>(std::max(bins, 1)));
  for (int i = 0; i < bins; ++i) f[static_cast<std::size_t>(i)] = left_of(2.0 * (i + 1) / bins - 1.0) - left_of(2.0 * i / bins - 1.0);
  return f;
}

std::optional<BifurcationStudySpec> parse_bifurcation_study(hs::common::ConfigSection root, const hs::common::Shape& shape) {
  if (!root.has("study")) return std::nullopt;
  hs::common::ConfigSection s = root.section("study");
  const auto* bif = dynamic_cast<const hs::common::Bifurcation*>(&shape);
  if (bif == nullptr) s.fail("branch_names", "the bifurcation study needs [geometry] shape = \"bifurcation\"");
  const hs::common::BifurcationSpec& g = bif->spec();
  BifurcationStudySpec c;
  c.junction_m = g.junction_m;
  const auto names = s.strings("branch_names", 2);
  if (names.size() != 2 || names[0] == names[1] || names[0] == "parent" || names[1] == "parent") {
    s.fail("branch_names", "must be 2 different names (daughters 0 and 1 of [geometry]), neither \"parent\"");
  }
  const Vec3 z{0.0, 0.0, 1.0};
  c.branches[0] = {.name = "parent", .direction = {-1.0, 0.0, 0.0}, .across = cross(z, Vec3{-1.0, 0.0, 0.0}),
                   .radius_m = g.parent_radius_m};
  for (int i = 0; i < 2; ++i) {
    const Vec3 d = bif->daughter_direction(i);
    c.branches[static_cast<std::size_t>(i) + 1] = {.name = names[static_cast<std::size_t>(i)], .direction = d,
                                                   .across = cross(z, d), .radius_m = g.daughter_radius_m[static_cast<std::size_t>(i)]};
  }
  c.cut_distance_m = s.positive("cut_distance_m");
  c.cut_thickness_m = s.positive("cut_thickness_m");
  if (c.cut_distance_m - 0.5 * c.cut_thickness_m <= g.parent_radius_m) {
    s.fail("cut_distance_m", fmt::format("the slab must start past the junction ball (parent radius {} m)", g.parent_radius_m));
  }
  for (int i = 0; i < 2; ++i) {
    if (c.cut_distance_m + 0.5 * c.cut_thickness_m >= g.daughter_length_m[static_cast<std::size_t>(i)]) {
      s.fail("cut_distance_m", fmt::format("reaches past daughter {}'s length {} m", i, g.daughter_length_m[static_cast<std::size_t>(i)]));
    }
  }
  c.profile_bins = static_cast<int>(s.integer_in_or("profile_bins", 2, 200, 10));
  const auto range = s.numbers_in("di_range", -10.0, 10.0, 2);
  if (range.size() != 2 || !(range[1] > range[0])) s.fail("di_range", "must be [lo, hi] with hi > lo");
  c.di_lo = range[0];
  c.di_hi = range[1];
  c.di_bins = static_cast<int>(s.integer_in_or("di_bins", 1, 1000, 40));
  c.di_threshold = s.number_in("di_threshold", c.di_lo, c.di_hi);
  return c;
}

}  // namespace hs::unresolved
