// SPDX-License-Identifier: MIT
// Named openings: the disc geometry and the checks that an opening cuts the domain where the fluid is.
#include "common/geometry/opening.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::common {
namespace {

// Directions sampled around the disc: 64 resolve a tube of 10 cells across to ~0.1% of its radius
// (1 - cos(pi/64) = 1.2e-3), far finer than the grid.
constexpr int n_rim_directions = 64;
// Rings sampled inside the disc (fractions of its radius), so a wall that pokes into the disc is found too.
constexpr std::array<double, 4> ring_fractions{0.25, 0.5, 0.75, 1.0};
// Geometric tolerance as a fraction of the box diagonal: coordinates typed in a case file or computed from
// lengths agree to ~1e-15 relative; 1e-9 accepts them and rejects any real offset (1e-9 of a 1 mm box is 1 pm).
constexpr double relative_tolerance = 1e-9;

struct Face {
  int axis = 0;
  bool high = false;       // the face at box.hi[axis]
  double distance_m = 0.0; // of the centre from the face plane
};

double diagonal_m(const Box3& b) { return norm(b.hi - b.lo); }

Face nearest_face(const Vec3& c, const Box3& b) {
  Face best{.axis = 0, .high = false, .distance_m = std::numeric_limits<double>::infinity()};
  for (int a = 0; a < 3; ++a) {
    for (const bool high : {false, true}) {
      const double d = std::abs(c[a] - (high ? b.hi[a] : b.lo[a]));
      if (d < best.distance_m) best = {.axis = a, .high = high, .distance_m = d};
    }
  }
  return best;
}

bool within_box(const Vec3& x, const Box3& b, double tol) {
  for (int a = 0; a < 3; ++a) {
    if (x[a] < b.lo[a] - tol || x[a] > b.hi[a] + tol) return false;
  }
  return true;
}

std::string show(const Vec3& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z); }

std::optional<OpeningProblem> disc_problem(const Opening& o, const Shape& shape, const Box3& domain, double tol) {
  const auto [t1, t2] = tangent_basis(o.normal);
  for (const double f : ring_fractions) {
    for (int k = 0; k < n_rim_directions; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / n_rim_directions;
      const Vec3 x = o.centre_m + f * o.radius_m * (std::cos(phi) * t1 + std::sin(phi) * t2);
      const double sd = shape.signed_distance(x);
      if (sd > tol || !within_box(x, domain, tol)) {
        const std::string where = sd > tol ? fmt::format("reaches {:.3g} m into the wall at {} m", sd, show(x))
                                           : fmt::format("leaves the domain box at {} m", show(x));
        return OpeningProblem{"radius_m", fmt::format("the disc {}; the largest disc inside the fluid and the box "
                                                      "here has radius_m = {:.6g}",
                                                      where, largest_inscribed_radius_m(o, shape, domain))};
      }
    }
  }
  return std::nullopt;
}

}  // namespace

const char* to_string(OpeningKind kind) { return kind == OpeningKind::inlet ? "inlet" : "outlet"; }

double Opening::lateral_m(const Vec3& x_m) const {
  const Vec3 r = x_m - centre_m;
  return norm(r - dot(r, normal) * normal);
}

double Opening::area_m2() const { return std::numbers::pi * radius_m * radius_m; }

std::pair<Vec3, Vec3> tangent_basis(const Vec3& n) {
  // Cross with the axis least aligned with n: well conditioned for every n.
  const Vec3 helper = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? Vec3{1, 0, 0}
                      : std::abs(n.y) <= std::abs(n.z)                               ? Vec3{0, 1, 0}
                                                                                     : Vec3{0, 0, 1};
  const Vec3 t1 = normalized(cross(n, helper));
  return {t1, cross(n, t1)};
}

std::optional<OpeningProblem> find_opening_problem(const Opening& o, const Shape& shape, const Box3& domain) {
  const double tol = relative_tolerance * diagonal_m(domain);
  if (o.name.empty()) return OpeningProblem{"name", "an opening needs a non-empty name"};
  if (!(o.radius_m > 0.0)) return OpeningProblem{"radius_m", "must be > 0"};
  if (!(std::abs(norm(o.normal) - 1.0) < 1e-9)) {
    return OpeningProblem{"normal", fmt::format("must be a unit vector (|normal| = {:.6g})", norm(o.normal))};
  }
  const Face face = nearest_face(o.centre_m, domain);
  if (face.distance_m > tol || !within_box(o.centre_m, domain, tol)) {
    return OpeningProblem{"centre_m", fmt::format("must lie on a face of the domain box {} .. {} m (it is {:.3g} m from "
                                                  "the nearest face, {} = {:.6g} m)",
                                                  show(domain.lo), show(domain.hi), face.distance_m, "xyz"[face.axis],
                                                  face.high ? domain.hi[face.axis] : domain.lo[face.axis])};
  }
  const double sd = shape.signed_distance(o.centre_m);
  if (!(sd < 0.0)) {
    return OpeningProblem{"centre_m", fmt::format("is not inside the fluid (signed distance {:.3g} m >= 0): the opening "
                                                  "does not cut the geometry's wall",
                                                  sd)};
  }
  Vec3 outward;
  outward[face.axis] = face.high ? 1.0 : -1.0;
  if (norm(o.normal - outward) > 1e-9) {
    return OpeningProblem{"normal", fmt::format("must be the outward normal {} of the face {} = {:.6g} m it lies on "
                                                "(pointing out of the fluid)",
                                                show(outward), "xyz"[face.axis], o.centre_m[face.axis])};
  }
  return disc_problem(o, shape, domain, tol);
}

std::optional<OpeningsProblem> find_openings_problem(const std::vector<Opening>& openings, const Shape& shape,
                                                     const Box3& domain) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < openings.size(); ++i) {
    const Opening& o = openings[i];
    if (auto p = find_opening_problem(o, shape, domain)) return OpeningsProblem{i, std::move(*p)};
    if (!names.insert(o.name).second) {
      return OpeningsProblem{i, {"name", "two openings have this name; names must be unique"}};
    }
    for (std::size_t j = 0; j < i; ++j) {
      const Opening& q = openings[j];
      const bool same_plane =
          norm(o.normal - q.normal) < 1e-9 && std::abs(q.height_m(o.centre_m)) < relative_tolerance * diagonal_m(domain);
      if (same_plane && norm(o.centre_m - q.centre_m) < o.radius_m + q.radius_m) {
        return OpeningsProblem{i, {"radius_m", fmt::format("the disc overlaps that of opening '{}' on the same face", q.name)}};
      }
    }
  }
  return std::nullopt;
}

void check_openings(const std::vector<Opening>& openings, const Shape& shape, const Box3& domain) {
  if (const auto p = find_openings_problem(openings, shape, domain)) {
    throw ConfigError(fmt::format("opening '{}': {}: {}", openings[p->index].name, p->problem.key, p->problem.what));
  }
}

double largest_inscribed_radius_m(const Opening& o, const Shape& shape, const Box3& domain) {
  const double reach = diagonal_m(domain);
  const auto [t1, t2] = tangent_basis(o.normal);
  double r_min = reach;
  for (int k = 0; k < n_rim_directions; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / n_rim_directions;
    const Vec3 t = std::cos(phi) * t1 + std::sin(phi) * t2;
    double s_box = reach;   // distance to the edge of the face along t
    for (int a = 0; a < 3; ++a) {
      if (t[a] > 1e-12) s_box = std::min(s_box, (domain.hi[a] - o.centre_m[a]) / t[a]);
      if (t[a] < -1e-12) s_box = std::min(s_box, (domain.lo[a] - o.centre_m[a]) / t[a]);
    }
    const Vec3 far = o.centre_m + s_box * t;
    double s = s_box;
    if (shape.signed_distance(far) >= 0.0) s = s_box * wall_crossing_fraction(shape, o.centre_m, far, 1e-9);
    r_min = std::min(r_min, s);
  }
  return std::max(r_min, 0.0);
}

}  // namespace hs::common
