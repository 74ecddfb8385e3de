// SPDX-License-Identifier: MIT
// The bifurcation study's measurement settings ([study] of an open-geometry case on a "bifurcation" shape) and its
// geometry: which branch a point is in, and where a point lies across a branch's cut (docs/bifurcation.md).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/config/config_file.hpp"
#include "common/geometry/shape.hpp"

namespace hs::unresolved {

struct StudyBranch {
  std::string name;                 // "parent", then [study] branch_names for daughters 0 and 1
  hs::common::Vec3 direction;       // unit, away from the junction (the parent's points upstream, -x)
  hs::common::Vec3 across;          // unit, z x direction: w grows along it
  double radius_m = 0.0;
};

struct BifurcationStudySpec {
  hs::common::Vec3 junction_m;
  std::array<StudyBranch, 3> branches;   // parent, daughter 0, daughter 1; the cuts are on 1 and 2
  double cut_distance_m = 0.0;           // from the junction along each daughter's axis
  double cut_thickness_m = 0.0;          // the slab around the cut plane that counts cells
  int profile_bins = 10;
  double di_lo = 0.0;                    // DI histogram range and bins
  double di_hi = 1.0;
  int di_bins = 20;
  double di_threshold = 0.5;             // the fraction of cells with DI above this is reported

  /// The branch (0 parent, 1 or 2 a daughter) whose axis ray from the junction is nearest to x.
  [[nodiscard]] int branch_of(const hs::common::Vec3& x_m) const;
  /// w = (s + R) / 2R across the cut of daughter `b` (1 or 2) when x lies in its slab (|t - cut| <= thickness / 2,
  /// t along the axis, s along `across`), else nothing.
  [[nodiscard]] std::optional<double> cut_coordinate(int b, const hs::common::Vec3& x_m) const;
  /// Fluid volume of each of the profile_bins equal strips of w across daughter b's slab (a circular section):
  /// pi R^2 thickness times disc_strip_fractions.
  [[nodiscard]] std::vector<double> cut_bin_fluid_m3(int b) const;
};

/// Share of a disc's area in each of n equal strips across its diameter (w = (s + R) / 2R): with
/// A(x) = x sqrt(1 - x^2) + asin(x), the area left of x = 2w - 1 is (A(x) + pi/2) / pi of the unit disc.
/// Sums to 1 and is symmetric. pre: bins >= 1.
[[nodiscard]] std::vector<double> disc_strip_fractions(int bins);

/// Reads [study] when the case has one (else nothing): branch_names (2 names), cut_distance_m, cut_thickness_m,
/// profile_bins, di_range ([lo, hi]), di_bins, di_threshold. ConfigError (exit 2) naming file, key and value when
/// the shape is not a bifurcation, a cut reaches past its branch's length, or the slab
/// would reach back into the junction ball (cut_distance_m - thickness / 2 must exceed the parent radius).
[[nodiscard]] std::optional<BifurcationStudySpec> parse_bifurcation_study(hs::common::ConfigSection root,
                                                                         const hs::common::Shape& shape);

}  // namespace hs::unresolved
