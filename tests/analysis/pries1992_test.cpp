// SPDX-License-Identifier: MIT
// Pries 1992 laws against the reference grid and the spot values of data/reference/README.md.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/pries1992.hpp"
#include "common/io/csv_writer.hpp"

using namespace hs::analysis;

TEST(Pries1992, SpotValues) {
  // data/reference (validation README): mu_045(50) = 2.045, mu_045(100) = 2.443, eta_rel(30, 0.15) = 1.171,
  // printed to 3 decimals, hence 5e-4.
  EXPECT_NEAR(relative_viscosity_at_045(50.0), 2.045, 5e-4);
  EXPECT_NEAR(relative_viscosity_at_045(100.0), 2.443, 5e-4);
  EXPECT_NEAR(relative_apparent_viscosity(30.0, 0.15), 1.171, 5e-4);
}

TEST(Pries1992, MatchesTheReferenceGrid) {
  const auto grid = hs::common::read_csv(std::string(HS_SOURCE_DIR) + "/data/reference/pries_grid.csv");
  ASSERT_GT(grid.rows.size(), 30u);
  const auto d = grid.column("D_um");
  const auto hd = grid.column("HD");
  const auto ratio = grid.column("HT_over_HD_Pries1992");
  const auto eta = grid.column("eta_rel_vitro_Pries1992");
  const auto c = grid.column("C_shape");
  for (std::size_t i = 0; i < d.size(); ++i) {
    // The grid is printed with 5 decimals: agreement to 6e-6 absolute is all it can show.
    EXPECT_NEAR(fahraeus_ratio(d[i], hd[i]), ratio[i], 6e-6) << "D = " << d[i] << " HD = " << hd[i];
    EXPECT_NEAR(relative_apparent_viscosity(d[i], hd[i]), eta[i], 6e-6) << "D = " << d[i] << " HD = " << hd[i];
    EXPECT_NEAR(viscosity_shape_exponent(d[i]), c[i], 6e-6);
  }
}

TEST(Pries1992, InverseFahraeusRoundTrips) {
  for (double d : {10.0, 30.0, 50.0, 100.0, 200.0}) {
    for (double hd : {0.05, 0.15, 0.3, 0.45}) {
      const double ht = hd * fahraeus_ratio(d, hd);
      EXPECT_NEAR(discharge_from_tube_hematocrit(d, ht), hd, 1e-14) << d << " " << hd;   // closed-form root
      EXPECT_LT(ht, hd);   // Fahraeus effect: tube hematocrit below discharge hematocrit
    }
  }
}
