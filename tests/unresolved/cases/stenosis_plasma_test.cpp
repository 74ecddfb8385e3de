// SPDX-License-Identifier: MIT
// The stenosis study's plasma-only check on a gentle constriction, where lubrication theory is accurate: the pressure
// drop against int 8 mu Q / (pi r^4) dx and the throat's centreline velocity against Poiseuille's 2 Q / (pi r_t^2).
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/cases/stenosis_plasma_check.hpp"

namespace hs::unresolved {
namespace {

// A 150 um tube narrowed to 120 um over 600 um (max wall slope 0.079: lubrication's error is O(slope^2) ~ 0.6%),
// 10 cells across the tube and 8 across the throat; the committed cases' fluid, flow rate and dt.
const char* kCase = R"(
[geometry]
shape = "stenosed-tube"
radius_m = 75e-6
throat_radius_m = 60e-6
constriction_length_m = 600e-6
constriction_centre_m = 450e-6
length_m = 900e-6
[openings.inlet]
kind = "inlet"
centre_m = [0.0, 0.0, 0.0]
normal = [-1.0, 0.0, 0.0]
radius_m = 75e-6
flow_rate_m3_s = 7.0686e-12
discharge_hematocrit = 0.05
[openings.outlet]
kind = "outlet"
centre_m = [900e-6, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]
radius_m = 75e-6
pressure_Pa = 0.0
[fluid]
density_kg_m3 = 1025.0
kinematic_viscosity_m2_s = 1.2e-6
[particles]
youngs_modulus_Pa = 1.0e3
[coupling]
drag = "stokes"
[study]
x_bins = 60
upstream_window_m = [30e-6, 100e-6]
downstream_window_m = [760e-6, 860e-6]
[numerics]
dx_m = 15e-6
dt_s = 1e-3
piso_correctors = 4
n_coupling = 640
end_time_s = 0.01
)";

TEST(StenosisPlasma, GentleConstrictionFollowsLubrication) {
  auto file = hs::common::ConfigFile::parse(kCase, "case.toml");
  const OpenGeometryConfig c = parse_open_geometry(*file, false);
  const StenosisPlasmaResult r = run_stenosis_plasma(c, c.dx_m, 400);
  std::printf("gentle stenosis, dx 15 um: drop %.4f Pa, lubrication %.4f Pa (ratio %.4f), throat centreline / (2 Q / A) = %.4f, "
              "%ld steps\n", r.pressure_drop_Pa, r.lubrication_drop_Pa, r.pressure_drop_Pa / r.lubrication_drop_Pa,
              r.throat_centreline_m_s / (2.0 * r.throat_mean_m_s), r.steps);
  EXPECT_LT(r.steps, 400);   // reached the steady Stokes flow
  // 2%: the cut-cell tube at 10 cells across carries its Poiseuille gradient within 0.7% (open_tube_openings_test:
  // 0.9929) and 8 cells across the throat about as well; lubrication's own error is O(slope^2) ~ 0.6% here.
  EXPECT_NEAR(r.pressure_drop_Pa / r.lubrication_drop_Pa, 1.0, 0.02);
  // The centreline speed against Poiseuille's 2 Q / (pi r_t^2) as the grid can give it: the axis lies on cell faces
  // here, so velocity_at interpolates the four nodes at r = dx / sqrt(2), which for a parabola gives
  // 1 - dx^2 / (2 r_t^2) = 0.969 of u_max. 4%: the nodes' parabola is scaled by the inlet's discrete-flux
  // normalisation (~0.7% at 10 cells across, open_tube_openings_test), and a throat is not a parallel flow: the
  // second-order lubrication terms are of the size of r_t r_t'' = 0.049 (the profile flattens where it curves).
  const double interpolated = 1.0 - c.dx_m * c.dx_m / (2.0 * 60e-6 * 60e-6);
  EXPECT_NEAR(r.throat_centreline_m_s / (2.0 * r.throat_mean_m_s * interpolated), 1.0, 0.04);
}

}  // namespace
}  // namespace hs::unresolved
