// SPDX-License-Identifier: MIT
// The flow boundary condition of a named opening (flow-rate inlet, pressure outlet, flow-split outlet), shared by
// the case file reader and the solvers that impose it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/opening.hpp"

namespace hs::common {

/// What the fluid does at an opening.
///  flow_rate_inlet:      a prescribed volume flow rate in, with a developed (parabolic) profile over the disc;
///  pressure_outlet:      a prescribed static pressure on the opening, zero normal gradient of the velocity;
///  flow_fraction_outlet: a prescribed share of the summed inlet flow rates out, with a developed profile.
enum class OpeningFlowType : std::uint8_t { flow_rate_inlet, pressure_outlet, flow_fraction_outlet };

[[nodiscard]] const char* to_string(OpeningFlowType type);

/// An opening and its condition. Only the field of its type is read; the others stay 0.
struct OpeningCondition {
  Opening opening;
  OpeningFlowType type = OpeningFlowType::pressure_outlet;
  double flow_rate_m3_s = 0.0;   // flow_rate_inlet: volume flow into the domain, > 0
  double pressure_Pa = 0.0;      // pressure_outlet: the pressure on the opening (the solver's gauge: any finite value)
  double flow_fraction = 0.0;    // flow_fraction_outlet: share of the summed inlet flow rates leaving here, in (0, 1]
};

/// A flow-rate inlet; the opening's kind must be inlet.
[[nodiscard]] OpeningCondition flow_rate_inlet(const Opening& opening, double flow_rate_m3_s);
/// A pressure outlet; the opening's kind must be outlet.
[[nodiscard]] OpeningCondition pressure_outlet(const Opening& opening, double pressure_Pa);
/// A flow-split outlet; the opening's kind must be outlet.
[[nodiscard]] OpeningCondition flow_fraction_outlet(const Opening& opening, double flow_fraction);

/// The first problem of a set of conditions beyond the geometry (find_openings_problem checks that): a type that does
/// not match the opening's kind (an inlet takes a flow rate, an outlet a pressure or a flow fraction), a value out of
/// range, flow fractions without an inlet, flow fractions summing to more than 1, or to other than 1 when no
/// pressure outlet takes the rest (the inflow would have nowhere to go). `index` is the opening at fault (for the
/// sum: the last flow-fraction outlet).
[[nodiscard]] std::optional<OpeningsProblem> find_conditions_problem(const std::vector<OpeningCondition>& conditions);

/// Throws ConfigError "opening 'NAME': key: what" for the first problem of the geometry (check_openings) or of the
/// conditions (find_conditions_problem).
void check_opening_conditions(const std::vector<OpeningCondition>& conditions, const Shape& shape, const Box3& domain);

}  // namespace hs::common
