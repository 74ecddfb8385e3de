// SPDX-License-Identifier: MIT
// The unit converter: round trips, the derived time step, and refusal of zero scales.
#include <gtest/gtest.h>

#include <stdexcept>

#include "common/units/unit_converter.hpp"

using hs::common::LatticeScales;
using hs::common::UnitConverter;

TEST(UnitConverter, RoundTripsEveryQuantity) {
  const UnitConverter u{LatticeScales{.dx_m = 5.0e-7, .dt_s = 1.25e-7, .rho_kg_m3 = 1025.0}};
  for (double v : {1e-3, 0.15, 7.0}) {   // relative 1e-15: two multiplications and one division
    EXPECT_NEAR(u.to_si_velocity(u.to_lattice_velocity(v)), v, 1e-15 * v);
    EXPECT_NEAR(u.to_si_force(u.to_lattice_force(v)), v, 1e-15 * v);
    EXPECT_NEAR(u.to_si_pressure(u.to_lattice_pressure(v)), v, 1e-15 * v);
    EXPECT_NEAR(u.to_si_force_density(u.to_lattice_force_density(v)), v, 1e-15 * v);
    EXPECT_NEAR(u.to_si_viscosity(u.to_lattice_viscosity(v)), v, 1e-15 * v);
    EXPECT_NEAR(u.to_si_length(u.to_lattice_length(v)), v, 1e-15 * v);
  }
}

TEST(UnitConverter, PalabosDefaultsGiveTheirTimeStep) {
  // resolved-methods.md 1.3: dx = 0.5 um, tau = 2, nu = 1e-6 m^2/s -> dt = 0.125 us; 0.15 m/s -> u_lb = 0.0375.
  const auto u = UnitConverter::from_relaxation_time(0.5e-6, 2.0, 1.0e-6, 1025.0);
  EXPECT_NEAR(u.dt_s(), 0.125e-6, 1e-20);
  EXPECT_NEAR(u.to_lattice_velocity(0.15), 0.0375, 1e-15);
  EXPECT_NEAR(u.to_lattice_viscosity(1.0e-6), 0.5, 1e-15);
}

TEST(UnitConverter, ForceScalesAsRhoDx4OverDt2) {
  const UnitConverter u{LatticeScales{.dx_m = 2.0, .dt_s = 4.0, .rho_kg_m3 = 3.0}};
  EXPECT_DOUBLE_EQ(u.to_si_force(1.0), 3.0 * 16.0 / 16.0);
  EXPECT_DOUBLE_EQ(u.to_si_force_density(1.0), 3.0 * 2.0 / 16.0);
  EXPECT_DOUBLE_EQ(u.to_si_pressure(1.0), 3.0 * 4.0 / 16.0);
}

TEST(UnitConverter, RefusesAMissingScale) {
  // The forgotten field is the point of this test, so silence the compiler's own warning about it.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
  EXPECT_THROW((UnitConverter{LatticeScales{.dx_m = 1e-6, .dt_s = 1e-7}}), std::invalid_argument);
#pragma GCC diagnostic pop
  EXPECT_THROW(UnitConverter::from_relaxation_time(1e-6, 0.5, 1e-6, 1000.0), std::invalid_argument);
}
