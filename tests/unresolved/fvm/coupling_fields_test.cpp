// SPDX-License-Identifier: MIT
// The fields the CFD-DEM coupling fills (void fraction, implicit Ksl with particle velocity, explicit force
// density) act as the model-A equation says, checked in a fully periodic box against the exact
// implicit-Euler solution of eps du/dt = -(Ksl/rho)(u - Us) + f/rho.
#include <gtest/gtest.h>

#include <cmath>

#include "unresolved/fvm/fvm_solver.hpp"
#include "../everywhere_shape.hpp"

namespace {

using hs::common::Vec3;
using hs::unresolved::FvmGrid;
using hs::unresolved::FvmGridSpec;
using hs::unresolved::FvmSolver;
using hs::unresolved::SideType;

using hs::test::Everywhere;

TEST(CouplingFields, ImplicitDragAndExplicitForceRelaxToTheirBalance) {
  const Everywhere all;
  FvmGridSpec spec{.box_m = {{0, 0, 0}, {4e-5, 4e-5, 4e-5}}, .dx_m = 1e-5, .sides = {}};
  for (auto& s : spec.sides) s.type = SideType::periodic;
  const FvmGrid grid(all, spec);
  const double rho = 1025.0;
  const double dt = 1e-4;
  FvmSolver solver(grid, {.density_kg_m3 = rho, .kinematic_viscosity_m2_s = 1.2e-6}, {.dt_s = dt}, {});
  const double eps = 0.6;
  const double ksl = 2e7;                   // kg m^-3 s^-1: Ksl dt / (rho eps) = 3.3, stiff on purpose
  const Vec3 us{1e-3, -2e-3, 0.0};          // m/s
  const Vec3 f{500.0, 0.0, 1000.0};         // N/m^3
  solver.void_fraction().fill(eps);
  solver.implicit_coefficient_kg_m3_s().fill(ksl);
  solver.particle_velocity_m_s().fill(us);
  solver.explicit_force_density_N_m3().fill(f);
  solver.coupling_fields_changed();
  const int steps = 5;
  for (int s = 0; s < steps; ++s) solver.step();
  // Implicit Euler: u_n = u_inf (1 - r^n), r = 1 / (1 + Ksl dt / (rho eps)), u_inf = Us + f / Ksl.
  const double r = 1.0 / (1.0 + ksl * dt / (rho * eps));
  const double factor = 1.0 - std::pow(r, steps);
  const Vec3 u = solver.velocity_at({1.3e-5, 2.7e-5, 0.4e-5});
  for (int c = 0; c < 3; ++c) {
    const double expected = (us[c] + f[c] / ksl) * factor;
    EXPECT_NEAR(u[c], expected, 1e-9 * std::abs(us[c] + f[c] / ksl) + 1e-15) << "component " << c;
  }
  EXPECT_NEAR(solver.pressure_gradient_at({2e-5, 2e-5, 2e-5}).x, 0.0, 1e-9);   // uniform flow: no pressure
}

}  // namespace
