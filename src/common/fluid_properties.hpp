// SPDX-License-Identifier: MIT
// The plasma (or any Newtonian carrier fluid) of a case, read from its [fluid] section the same way in both stages.
#pragma once

#include "common/config/config_file.hpp"

namespace hs::common {

struct FluidProperties {
  double density_kg_m3;
  double kinematic_viscosity_m2_s;

  [[nodiscard]] double dynamic_viscosity_Pa_s() const { return density_kg_m3 * kinematic_viscosity_m2_s; }
};

/// [fluid] density_kg_m3 (plasma: 1025) and kinematic_viscosity_m2_s (plasma: about 1.0e-6 to 1.2e-6), both
/// required and > 0 (resolved-methods.md section 1.3; rbc_blood_properties.csv).
inline FluidProperties parse_fluid(ConfigSection fluid) {
  return {.density_kg_m3 = fluid.positive("density_kg_m3"),
          .kinematic_viscosity_m2_s = fluid.positive("kinematic_viscosity_m2_s")};
}

}  // namespace hs::common
