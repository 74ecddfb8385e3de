// SPDX-License-Identifier: MIT
// Reading [openings.NAME] sections: the openings' geometry and, for the fluid solver, their flow conditions.
#include "common/geometry/openings_from_config.hpp"

#include <string>

namespace hs::common {
namespace {

Vec3 vector_of(ConfigSection& s, std::string_view key) {
  const auto v = s.numbers_in(key, -1e300, 1e300, 3);
  if (v.size() != 3) s.fail(key, "must have exactly 3 values [x, y, z]");
  return {v[0], v[1], v[2]};
}

Opening read_opening(ConfigSection& s, const std::string& name) {
  Opening o;
  o.name = name;
  o.kind = s.one_of("kind", {"inlet", "outlet"}) == "inlet" ? OpeningKind::inlet : OpeningKind::outlet;
  o.centre_m = vector_of(s, "centre_m");
  const Vec3 n = vector_of(s, "normal");
  if (!(norm(n) > 0.0)) s.fail("normal", "must be a non-zero vector");
  o.normal = normalized(n);
  o.radius_m = s.positive("radius_m");
  return o;
}

/// The condition keys: an inlet takes flow_rate_m3_s only; an outlet exactly one of pressure_Pa and flow_fraction.
OpeningCondition read_condition(ConfigSection& s, const Opening& o) {
  if (o.kind == OpeningKind::inlet) {
    for (const char* key : {"pressure_Pa", "flow_fraction"}) {
      if (s.has(key)) s.fail(key, "is for an outlet; an inlet takes flow_rate_m3_s (m^3/s, > 0)");
    }
    return flow_rate_inlet(o, s.positive("flow_rate_m3_s"));
  }
  if (s.has("flow_rate_m3_s")) {
    s.fail("flow_rate_m3_s",
           "is for an inlet; an outlet takes pressure_Pa (Pa) or flow_fraction (share of the inflow)");
  }
  s.forbid_together("pressure_Pa", "flow_fraction", "an outlet either holds a pressure or takes a share of the inflow");
  if (s.has("pressure_Pa")) return pressure_outlet(o, s.number_in("pressure_Pa", -1e300, 1e300));
  if (s.has("flow_fraction")) return flow_fraction_outlet(o, s.number_in("flow_fraction", 0.0, 1.0));
  s.fail("pressure_Pa", "missing: an outlet needs pressure_Pa (its pressure, Pa) or flow_fraction (its share of the "
                        "summed inlet flow rates, in (0, 1])");
}

}  // namespace

std::vector<Opening> openings_from_config(ConfigSection openings, const Shape& shape, const Box3& domain) {
  std::vector<Opening> out;
  std::vector<ConfigSection> sections;
  for (const std::string& name : openings.keys()) {
    ConfigSection s = openings.section(name);
    out.push_back(read_opening(s, name));
    sections.push_back(s);
  }
  if (const auto p = find_openings_problem(out, shape, domain)) sections[p->index].fail(p->problem.key, p->problem.what);
  return out;
}

std::vector<OpeningCondition> opening_conditions_from_config(ConfigSection openings, const Shape& shape,
                                                             const Box3& domain) {
  std::vector<OpeningCondition> out;
  std::vector<Opening> geometry;
  std::vector<ConfigSection> sections;
  for (const std::string& name : openings.keys()) {
    ConfigSection s = openings.section(name);
    geometry.push_back(read_opening(s, name));
    out.push_back(read_condition(s, geometry.back()));
    sections.push_back(s);
  }
  if (const auto p = find_openings_problem(geometry, shape, domain)) {
    sections[p->index].fail(p->problem.key, p->problem.what);
  }
  if (const auto p = find_conditions_problem(out)) sections[p->index].fail(p->problem.key, p->problem.what);
  return out;
}

}  // namespace hs::common
