// SPDX-License-Identifier: MIT
// The tube-pries tests' small tube as case.toml text: D = L = 30 um, 10 cells across, 0.2 ms CFD steps, plasma.
#pragma once

#include <string>

namespace hs::test {

/// `hematocrit` and `n_coupling` as written in the file; `coupling` the [coupling] lines (empty: the section is
/// left out); `tail` any sections after [numerics] (e.g. "[output]\n...").
inline std::string short_tube_case(const std::string& hematocrit, const std::string& coupling, const std::string& n_coupling,
                                   const std::string& end_time_s, const std::string& tail = "") {
  return R"([case]
type = "tube-pries"
[geometry]
diameter_m = 30e-6
length_m = 30e-6
[fluid]
density_kg_m3 = 1025.0
kinematic_viscosity_m2_s = 1.2e-6
[flow]
pressure_gradient_Pa_m = -4.4e4
[cells]
tube_hematocrit = )" + hematocrit + R"(
[particles]
youngs_modulus_Pa = 1.0e3
)" + (coupling.empty() ? std::string() : "[coupling]\n" + coupling) +
         R"([numerics]
cells_across_diameter = 10
dt_s = 2e-4
n_coupling = )" + n_coupling + "\nend_time_s = " + end_time_s + "\n" + tail;
}

}  // namespace hs::test
