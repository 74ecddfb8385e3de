// SPDX-License-Identifier: MIT
// A named opening of a flow geometry (an inlet or outlet patch, as OpenFOAM names its patches) and the check
// that it really is where the fluid meets the domain boundary.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry/shape.hpp"

namespace hs::common {

enum class OpeningKind { inlet, outlet };

[[nodiscard]] const char* to_string(OpeningKind kind);

/// The patch is the disc of radius `radius_m` around `centre_m` in the plane normal to `normal`; `normal` is a
/// unit vector pointing out of the fluid (for an inlet too: the fluid enters against it).
struct Opening {
  std::string name;
  OpeningKind kind = OpeningKind::inlet;
  Vec3 centre_m;
  Vec3 normal;
  double radius_m = 0.0;

  /// Signed height of x above the opening's plane: > 0 beyond it (outside the domain), < 0 in the fluid side.
  [[nodiscard]] double height_m(const Vec3& x_m) const { return dot(x_m - centre_m, normal); }
  /// Distance of x from the line through the centre along the normal.
  [[nodiscard]] double lateral_m(const Vec3& x_m) const;
  [[nodiscard]] double area_m2() const;
};

/// Two unit vectors that make (t1, t2, n) a right-handed orthonormal basis. pre: |n| = 1.
[[nodiscard]] std::pair<Vec3, Vec3> tangent_basis(const Vec3& n);

/// What is wrong with an opening: the key (as in a case file's [openings.NAME] section) and why.
struct OpeningProblem {
  std::string key;
  std::string what;
};

/// An opening is valid on the Cartesian domain `domain` (the FVM/DEM box) when: it has a name; radius_m > 0;
/// its centre lies on a face of the box and inside the shape (signed distance < 0); its normal is that face's
/// outward normal (the box faces are the only planes a Cartesian grid can cut); and its disc lies inside the
/// shape's cross-section and within the face. Returns the first problem found, or nothing.
[[nodiscard]] std::optional<OpeningProblem> find_opening_problem(const Opening& opening, const Shape& shape,
                                                                 const Box3& domain);

/// The first problem of a set of openings: of one opening (find_opening_problem), two with the same name, or two
/// discs overlapping on one face. `index` is the index of the opening at fault.
struct OpeningsProblem {
  std::size_t index;
  OpeningProblem problem;
};
[[nodiscard]] std::optional<OpeningsProblem> find_openings_problem(const std::vector<Opening>& openings,
                                                                   const Shape& shape, const Box3& domain);

/// Throws ConfigError "opening 'NAME': key: what" for the first problem of find_openings_problem.
void check_openings(const std::vector<Opening>& openings, const Shape& shape, const Box3& domain);

/// The largest radius (to 1e-9 of the box size) of a disc around the opening's centre, in its plane, inside the
/// shape: what a user may give as radius_m. Sampled in 64 directions.
[[nodiscard]] double largest_inscribed_radius_m(const Opening& opening, const Shape& shape, const Box3& domain);

}  // namespace hs::common
