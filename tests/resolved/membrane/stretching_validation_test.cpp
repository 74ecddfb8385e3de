// SPDX-License-Identifier: MIT
// Validation against Mills et al. 2004 (Mech Chem Biosyst 1:169), optical tweezers, 2 um contact patches:
// the default membrane parameters (one set for all forces) must put axial and transverse diameters inside the
// experimental band at three force levels (low, middle, top of the range), conserve area and volume within 1% at
// 193 pN, and give the same answer at 258 and 642 vertices (mesh independence). The full 13-level comparison is
// `hemoscale validate stretching`.
#include <gtest/gtest.h>

#include <cmath>

#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/stretching_experiment.hpp"
#include "resolved/membrane/stretching_reference.hpp"

using namespace hs::resolved;

namespace {

/// Each long quasi-static step is allowed to converge (the default 30 iterations suit 0.25 us coupled steps).
NpfemSettings quasi_static_settings() {
  NpfemSettings s;
  s.max_iterations = 300;
  return s;
}

const StretchingBandPoint& band_at(const std::vector<StretchingBandPoint>& band, double force_pN) {
  for (const auto& b : band)
    if (std::abs(b.force_N * 1e12 - force_pN) < 0.05) return b;
  throw std::runtime_error("force level not in the Mills table");
}

std::vector<StretchingPoint> run_levels(int vertices, const std::vector<double>& forces_pN,
                                       const MembraneParameters& membrane = MembraneParameters{}) {
  StretchingExperiment experiment(make_rbc_mesh({.vertex_count = vertices}), membrane, quasi_static_settings(),
                                  StretchingSetup{});
  std::vector<StretchingPoint> out;
  for (const double f : forces_pN) out.push_back(experiment.run_force(f * 1e-12));
  return out;
}

}  // namespace

TEST(StretchingValidation, ThreeForceLevelsInsideTheMillsBandAt258Vertices) {
  const auto band = read_stretching_band(default_stretching_band_csv());
  const std::vector<double> forces_pN = {19.5, 108.8, 193.0};
  const auto points = run_levels(258, forces_pN);
  for (std::size_t i = 0; i < forces_pN.size(); ++i) {
    const auto& b = band_at(band, forces_pN[i]);
    EXPECT_TRUE(points[i].steady) << forces_pN[i];
    EXPECT_TRUE(b.axial_inside(points[i].axial_m)) << forces_pN[i] << " pN: axial " << points[i].axial_m * 1e6 << " um";
    EXPECT_TRUE(b.transverse_inside(points[i].transverse_m))
        << forces_pN[i] << " pN: transverse " << points[i].transverse_m * 1e6 << " um";
  }
  // Issue 3 acceptance: area and volume conserved within 1% at 193 pN.
  EXPECT_LT(std::abs(points.back().area_change), 0.01);
  EXPECT_LT(std::abs(points.back().volume_change), 0.01);
}

TEST(StretchingValidation, SameShearModulusGivesTheSameCurveAt642Vertices) {
  const auto band = read_stretching_band(default_stretching_band_csv());
  const std::vector<double> forces_pN = {108.8, 193.0};
  const auto coarse = run_levels(258, forces_pN);
  const auto fine = run_levels(642, forces_pN);
  for (std::size_t i = 0; i < forces_pN.size(); ++i) {
    const auto& b = band_at(band, forces_pN[i]);
    EXPECT_TRUE(b.axial_inside(fine[i].axial_m)) << forces_pN[i] << " pN: axial " << fine[i].axial_m * 1e6;
    EXPECT_TRUE(b.transverse_inside(fine[i].transverse_m)) << forces_pN[i] << " pN: transverse " << fine[i].transverse_m * 1e6;
    // Axial: 2%, a fifth of the Mills band's half-width here (+-10.3% at 108.8 pN, +-10.8% at 193 pN): the mesh may
    // not move a result across more than a fifth of the experimental uncertainty. (Measured between the octahedron-258
    // and icosahedron-642 meshes: 1.4% and 0.3%; 3% at 16 pN, outside this test.) The transverse diameter is more
    // mesh-sensitive (measured +5% at 108.8 pN, +7% at 193 pN at 642 vertices): only its band is asserted.
    EXPECT_NEAR(fine[i].axial_m / coarse[i].axial_m, 1.0, 0.02) << forces_pN[i];
  }
}

TEST(StretchingValidation, NegativeControlTwiceTheShearModulusLeavesTheMillsBand) {
  // The band must be able to fail: at small strain the stretch goes as F / mu, so a membrane twice as stiff as the
  // default (2.5 uN/m) stretches about half as far, below the band's lower axial edge at the upper forces.
  const auto band = read_stretching_band(default_stretching_band_csv());
  MembraneParameters stiff;
  stiff.shear_modulus_N_m *= 2.0;
  const std::vector<double> forces_pN = {108.8, 193.0};
  const auto points = run_levels(258, forces_pN, stiff);
  int outside = 0;
  for (std::size_t i = 0; i < forces_pN.size(); ++i) {
    const auto& b = band_at(band, forces_pN[i]);
    if (!b.axial_inside(points[i].axial_m) || !b.transverse_inside(points[i].transverse_m)) ++outside;
  }
  EXPECT_EQ(outside, 2) << "a 2x shear modulus stayed inside the Mills band";
}
