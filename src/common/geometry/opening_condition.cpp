// SPDX-License-Identifier: MIT
// Flow conditions of named openings: constructors and the consistency checks.
#include "common/geometry/opening_condition.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::common {
namespace {

/// Flow fractions given with ~15 digits sum to 1 within ~1e-15; 1e-9 accepts typed decimals (0.3 + 0.7) and rejects
/// any real imbalance (1e-9 of the inflow lost at every step would be a visible mass leak only after 1e9 steps).
constexpr double kFractionSumTolerance = 1e-9;

std::optional<OpeningProblem> type_problem(const OpeningCondition& c) {
  const bool inlet = c.opening.kind == OpeningKind::inlet;
  switch (c.type) {
    case OpeningFlowType::flow_rate_inlet:
      if (!inlet) {
        return OpeningProblem{"flow_rate_m3_s", "is for an inlet; an outlet takes pressure_Pa or flow_fraction"};
      }
      if (!(c.flow_rate_m3_s > 0.0) || !std::isfinite(c.flow_rate_m3_s)) {
        return OpeningProblem{"flow_rate_m3_s",
                              fmt::format("= {} must be a finite volume flow rate > 0 (m^3/s, into the domain)",
                                          c.flow_rate_m3_s)};
      }
      return std::nullopt;
    case OpeningFlowType::pressure_outlet:
      if (inlet) return OpeningProblem{"pressure_Pa", "is for an outlet; an inlet takes flow_rate_m3_s"};
      if (!std::isfinite(c.pressure_Pa)) {
        return OpeningProblem{"pressure_Pa", fmt::format("= {} must be a finite pressure (Pa)", c.pressure_Pa)};
      }
      return std::nullopt;
    case OpeningFlowType::flow_fraction_outlet:
      if (inlet) return OpeningProblem{"flow_fraction", "is for an outlet; an inlet takes flow_rate_m3_s"};
      if (!(c.flow_fraction > 0.0 && c.flow_fraction <= 1.0)) {
        return OpeningProblem{"flow_fraction",
                              fmt::format("= {} must lie in (0, 1]: the share of the summed inlet flow rates leaving "
                                          "through this outlet",
                                          c.flow_fraction)};
      }
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

const char* to_string(OpeningFlowType type) {
  switch (type) {
    case OpeningFlowType::flow_rate_inlet: return "flow_rate_inlet";
    case OpeningFlowType::pressure_outlet: return "pressure_outlet";
    case OpeningFlowType::flow_fraction_outlet: return "flow_fraction_outlet";
  }
  return "?";
}

OpeningCondition flow_rate_inlet(const Opening& opening, double flow_rate_m3_s) {
  return {.opening = opening, .type = OpeningFlowType::flow_rate_inlet, .flow_rate_m3_s = flow_rate_m3_s};
}

OpeningCondition pressure_outlet(const Opening& opening, double pressure_Pa) {
  return {.opening = opening, .type = OpeningFlowType::pressure_outlet, .pressure_Pa = pressure_Pa};
}

OpeningCondition flow_fraction_outlet(const Opening& opening, double flow_fraction) {
  return {.opening = opening, .type = OpeningFlowType::flow_fraction_outlet, .flow_fraction = flow_fraction};
}

std::optional<OpeningsProblem> find_conditions_problem(const std::vector<OpeningCondition>& conditions) {
  bool inlet = false;
  bool pressure = false;
  double fraction_sum = 0.0;
  std::optional<std::size_t> last_fraction;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    if (auto p = type_problem(conditions[i])) return OpeningsProblem{i, std::move(*p)};
    inlet = inlet || conditions[i].type == OpeningFlowType::flow_rate_inlet;
    pressure = pressure || conditions[i].type == OpeningFlowType::pressure_outlet;
    if (conditions[i].type == OpeningFlowType::flow_fraction_outlet) {
      fraction_sum += conditions[i].flow_fraction;
      last_fraction = i;
    }
  }
  if (!last_fraction) return std::nullopt;
  if (!inlet) {
    return OpeningsProblem{*last_fraction,
                           {"flow_fraction", "needs at least one inlet with flow_rate_m3_s: the fraction is a share of "
                                             "the summed inlet flow rates"}};
  }
  const bool too_much = fraction_sum > 1.0 + kFractionSumTolerance;
  if (too_much || (!pressure && std::abs(fraction_sum - 1.0) > kFractionSumTolerance)) {
    return OpeningsProblem{*last_fraction,
                           {"flow_fraction",
                            fmt::format("the flow fractions of the outlets sum to {:.9g}; they must sum to 1 {}",
                                        fraction_sum,
                                        pressure ? "at most (a pressure outlet takes the rest)"
                                                 : "exactly when no outlet has pressure_Pa")}};
  }
  return std::nullopt;
}

void check_opening_conditions(const std::vector<OpeningCondition>& conditions, const Shape& shape, const Box3& domain) {
  std::vector<Opening> openings;
  openings.reserve(conditions.size());
  for (const auto& c : conditions) openings.push_back(c.opening);
  check_openings(openings, shape, domain);
  if (const auto p = find_conditions_problem(conditions)) {
    throw ConfigError(
        fmt::format("opening '{}': {}: {}", conditions[p->index].opening.name, p->problem.key, p->problem.what));
  }
}

}  // namespace hs::common
