// SPDX-License-Identifier: MIT
// The suspension viscosity laws and the smoothed volume fraction they are given.
#include <stdexcept>

#include <gtest/gtest.h>

#include "analysis/pries1992.hpp"
#include "common/errors.hpp"
#include "unresolved/coupling/bulk_blood_viscosity.hpp"
#include "unresolved/coupling/suspension_viscosity.hpp"
#include "periodic_tube.hpp"

namespace {

using namespace hs::unresolved;

TEST(SuspensionViscosity, LawsAtTheirDefiningPoints) {
  EXPECT_DOUBLE_EQ(relative_viscosity(SuspensionViscosity::none, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(relative_viscosity(SuspensionViscosity::einstein, 0.1), 1.25);   // 1 + 2.5 phi
  EXPECT_DOUBLE_EQ(relative_viscosity(SuspensionViscosity::pries_bulk, 0.0), 1.0);
  EXPECT_NEAR(relative_viscosity(SuspensionViscosity::pries_bulk, 0.45), 3.2, 1e-12);   // mu_0.45 of a wide tube
  // The wide-tube limit of the diameter-dependent law: at D = 10 mm it is that law to 1e-9 (the test reads analysis/;
  // the solver does not).
  for (const double h : {0.05, 0.15, 0.3}) {
    EXPECT_NEAR(bulk_blood_relative_viscosity(h), hs::analysis::relative_apparent_viscosity(1e4, h), 1e-9);
  }
  EXPECT_THROW((void)bulk_blood_relative_viscosity(1.0), std::invalid_argument);
  EXPECT_EQ(suspension_viscosity_from_name("pries_bulk"), SuspensionViscosity::pries_bulk);
  EXPECT_EQ(suspension_viscosity_name(SuspensionViscosity::einstein), "einstein");
  EXPECT_THROW((void)suspension_viscosity_from_name("quemada"), hs::common::ConfigError);
}

TEST(SuspensionViscosity, FactorFollowsTheVolumeFractionAveragedOverNeighbours) {
  const hs::common::Tube tube = test::tube_along_z(30e-6, 30e-6);
  const FvmGrid grid = test::periodic_tube_grid(tube, 30e-6, 30e-6);
  BlockField<double> eps(grid.cells(), 0.8);
  BlockField<double> factor(grid.cells(), 0.0);
  fill_cell_field_ghosts(grid, eps);
  fill_viscosity_factor(grid, SuspensionViscosity::einstein, eps, factor);
  // Uniform phi = 0.2 in every fluid cell, the wall cells included (only fluid neighbours count).
  EXPECT_DOUBLE_EQ(factor(5, 5, 5), 1.5);
  EXPECT_NEAR(factor(0, 5, 5), 1.5, 1e-12);
  // One cell at phi = 0.9 in clear plasma: each of its 26 neighbours and itself see 0.9 / 27 (interior cells).
  eps = BlockField<double>(grid.cells(), 1.0);
  eps(5, 5, 5) = 0.1;
  fill_cell_field_ghosts(grid, eps);
  fill_viscosity_factor(grid, SuspensionViscosity::einstein, eps, factor);
  EXPECT_NEAR(factor(5, 5, 5), 1.0 + 2.5 * 0.9 / 27.0, 1e-12);
  EXPECT_NEAR(factor(6, 6, 4), 1.0 + 2.5 * 0.9 / 27.0, 1e-12);
  EXPECT_DOUBLE_EQ(factor(7, 5, 5), 1.0);
}

}  // namespace
