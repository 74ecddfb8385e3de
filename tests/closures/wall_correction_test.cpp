// SPDX-License-Identifier: MIT
// Haberman-Sayre confinement factor against the tabulated K(d/D) of a sphere on a tube axis.
#include <gtest/gtest.h>

#include <filesystem>

#include "closures/wall_correction.hpp"
#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"

namespace {

using namespace hs::closures;

TEST(WallCorrection, HabermanSayreMatchesTheTabulatedFactor) {
  const auto table = hs::common::read_csv(std::filesystem::path(HS_SOURCE_DIR) / "data/reference/sphere_in_tube_wall_correction.csv");
  const auto lambda = table.column("lambda_d_over_D");
  const auto k_hs = table.column("K_Haberman_Sayre_1958");
  const auto k_bohlin = table.column("K_Bohlin_series");
  int checked = 0;
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    if (lambda[i] > kMaxConfinementLambda) continue;
    // The table prints 6 significant digits: 1e-5 relative is its rounding.
    EXPECT_NEAR(haberman_sayre_factor(lambda[i]), k_hs[i], 1e-5 * k_hs[i]) << "lambda " << lambda[i];
    // Independent check of the formula's accuracy where it is accepted: Bohlin's series within 4.2% (0.6), 0.2% (<= 0.4).
    const double tol = lambda[i] <= 0.4 ? 2e-3 : 4.5e-2;
    EXPECT_NEAR(haberman_sayre_factor(lambda[i]), k_bohlin[i], tol * k_bohlin[i]) << "lambda " << lambda[i];
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

TEST(WallCorrection, FactorOfAnRbcSphereInPriesTubes) {
  const double d_p = 5.64e-6;   // volume-equivalent sphere of a 94.1 um^3 RBC
  EXPECT_DOUBLE_EQ(wall_correction_factor(WallCorrection::none, d_p, 30e-6), 1.0);
  const double k30 = wall_correction_factor(WallCorrection::haberman_sayre, d_p, 30e-6);
  const double k100 = wall_correction_factor(WallCorrection::haberman_sayre, d_p, 100e-6);
  EXPECT_GT(k30, k100);
  EXPECT_GT(k100, 1.0);
  // Bracketed by the table's K(0.1) = 1.2633 and K(0.2) = 1.67972 at lambda = 0.188.
  EXPECT_GT(k30, 1.2633);
  EXPECT_LT(k30, 1.67972);
}

TEST(WallCorrection, BadInputsAreConfigErrors) {
  EXPECT_THROW((void)wall_correction_from_name("faxen"), hs::common::ConfigError);
  EXPECT_EQ(wall_correction_from_name("haberman_sayre"), WallCorrection::haberman_sayre);
  EXPECT_EQ(wall_correction_name(WallCorrection::none), "none");
  EXPECT_THROW((void)haberman_sayre_factor(0.7), hs::common::ConfigError);
  EXPECT_THROW((void)wall_correction_factor(WallCorrection::haberman_sayre, 10e-6, 12e-6), hs::common::ConfigError);
}

TEST(WallCorrection, RelativeFactorIsOneInTheLearnedClosuresTube) {
  // The learned closures already hold their 50 um tube's confinement: there the relative factor is 1, and in a
  // narrower tube it is the ratio of the two on-axis factors (1.24 at D = 30 um for d_p = 5.6 um, docs/cfd-dem.md).
  const double d_p = 5.597e-6;
  const auto relative = WallCorrection::haberman_sayre_relative;
  EXPECT_DOUBLE_EQ(wall_correction_factor(relative, d_p, kLearnedClosureTubeDiameter_m), 1.0);
  const double ratio = haberman_sayre_factor(d_p / 30e-6) / haberman_sayre_factor(d_p / 50e-6);
  EXPECT_DOUBLE_EQ(wall_correction_factor(relative, d_p, 30e-6), ratio);
  EXPECT_NEAR(ratio, 1.236, 1e-3);   // K(0.1866) / K(0.1119) = 1.6114 / 1.3033
  EXPECT_LT(wall_correction_factor(relative, d_p, 100e-6), 1.0);   // a wider tube than the fit's: less drag
  EXPECT_EQ(wall_correction_from_name("haberman_sayre_relative"), relative);
  EXPECT_EQ(wall_correction_name(relative), "haberman_sayre_relative");
}

}  // namespace
