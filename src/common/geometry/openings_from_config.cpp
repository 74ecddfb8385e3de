// SPDX-License-Identifier: MIT
// Reading [openings.NAME] sections.
#include "common/geometry/openings_from_config.hpp"

#include <string>

namespace hs::common {
namespace {

Vec3 vector_of(ConfigSection& s, std::string_view key) {
  const auto v = s.numbers_in(key, -1e300, 1e300, 3);
  if (v.size() != 3) s.fail(key, "must have exactly 3 values [x, y, z]");
  return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<Opening> openings_from_config(ConfigSection openings, const Shape& shape, const Box3& domain) {
  std::vector<Opening> out;
  std::vector<ConfigSection> sections;
  for (const std::string& name : openings.keys()) {
    ConfigSection s = openings.section(name);
    Opening o;
    o.name = name;
    o.kind = s.one_of("kind", {"inlet", "outlet"}) == "inlet" ? OpeningKind::inlet : OpeningKind::outlet;
    o.centre_m = vector_of(s, "centre_m");
    const Vec3 n = vector_of(s, "normal");
    if (!(norm(n) > 0.0)) s.fail("normal", "must be a non-zero vector");
    o.normal = normalized(n);
    o.radius_m = s.positive("radius_m");
    out.push_back(o);
    sections.push_back(s);
  }
  if (const auto p = find_openings_problem(out, shape, domain)) sections[p->index].fail(p->problem.key, p->problem.what);
  return out;
}

}  // namespace hs::common
