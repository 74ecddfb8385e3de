// SPDX-License-Identifier: MIT
// Confinement (wall) correction of the drag on a sphere in a circular tube: Haberman & Sayre (1958).
#include "closures/wall_correction.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::closures {

double haberman_sayre_factor(double lambda) {
  if (!(lambda >= 0.0 && lambda <= kMaxConfinementLambda)) {
    throw hs::common::ConfigError(fmt::format("wall correction: confinement d_p / D = {:.4g} is outside [0, {}] where the "
                                              "Haberman-Sayre factor is accurate (use a wider tube or wall_correction = \"none\")",
                                              lambda, kMaxConfinementLambda));
  }
  const double l3 = lambda * lambda * lambda;
  const double l5 = l3 * lambda * lambda;
  const double l6 = l5 * lambda;
  return (1.0 - 0.75857 * l5) / (1.0 - 2.1050 * lambda + 2.0865 * l3 - 1.7068 * l5 + 0.72603 * l6);
}

WallCorrection wall_correction_from_name(std::string_view name) {
  if (name == "none") return WallCorrection::none;
  if (name == "haberman_sayre") return WallCorrection::haberman_sayre;
  if (name == "haberman_sayre_relative") return WallCorrection::haberman_sayre_relative;
  throw hs::common::ConfigError(fmt::format(
      "unknown wall correction \"{}\" (allowed: \"none\", \"haberman_sayre\", \"haberman_sayre_relative\")", name));
}

std::string wall_correction_name(WallCorrection w) {
  switch (w) {
    case WallCorrection::haberman_sayre: return "haberman_sayre";
    case WallCorrection::haberman_sayre_relative: return "haberman_sayre_relative";
    case WallCorrection::none: break;
  }
  return "none";
}

double wall_correction_factor(WallCorrection w, double particle_diameter_m, double tube_diameter_m) {
  if (w == WallCorrection::none) return 1.0;
  if (!(tube_diameter_m > 0.0)) throw hs::common::ConfigError("wall correction: the tube diameter must be > 0");
  const double k = haberman_sayre_factor(particle_diameter_m / tube_diameter_m);
  if (w == WallCorrection::haberman_sayre) return k;
  return k / haberman_sayre_factor(particle_diameter_m / kLearnedClosureTubeDiameter_m);
}

}  // namespace hs::closures
