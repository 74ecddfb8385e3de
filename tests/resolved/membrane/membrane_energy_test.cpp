// SPDX-License-Identifier: MIT
// The membrane energies: analytic gradients vs finite differences, the triangle law against Skalak et al. 1973 in pure
// and simple shear, and the bending normalisation against the Helfrich energy of a sphere.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "resolved/membrane/membrane_energy.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

using namespace hs::resolved;

namespace {

Positions to_um(const TriangleMesh& m) {
  Positions x(m.vertex_count(), 3);
  for (int i = 0; i < m.vertex_count(); ++i) x.row(i) << m.vertices_m[i].x * 1e6, m.vertices_m[i].y * 1e6, m.vertices_m[i].z * 1e6;
  return x;
}

// Moduli of the order of the defaults (internal units pN/um etc.), all terms switched on.
EnergyModuli all_terms() {
  return {.skalak_lambda_pN_um = 10.0, .hardening_mu_pN_um = 10.0, .area_weight_pN_um = 50.0, .bending_pN_um = 0.2,
          .volume_modulus_pN_um2 = 300.0, .global_area_pN_um = 20.0};
}


/// A scalene triangle spanned in the plane of the orthonormal t1, t2 (edge lengths ~ scale).
Positions flat_triangle(const Eigen::Vector3d& t1, const Eigen::Vector3d& t2, double scale) {
  Positions x(3, 3);
  x.row(0) = Eigen::RowVector3d::Zero();
  x.row(1) = scale * t1.transpose();
  x.row(2) = scale * (0.35 * t1 + 0.8 * t2).transpose();
  return x;
}

/// An n x n grid of unit squares in the x-y plane, each split into two triangles (an open, flat patch).
Positions flat_patch(int n) {
  Positions x((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) x.row(j * (n + 1) + i) << i, j + 0.3 * i, 0.0;   // sheared grid: non-right triangles
  return x;
}

std::vector<std::array<int, 3>> patch_triangles(int n) {
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      t.push_back({v, v + 1, v + n + 2});
      t.push_back({v, v + n + 2, v + n + 1});
    }
  }
  return t;
}

}  // namespace

TEST(MembraneEnergy, RestShapeHasZeroEnergyAndForce) {
  const TriangleMesh m = make_rbc_mesh({.vertex_count = 66});
  MembraneEnergy e(to_um(m), m.triangles, all_terms());
  Positions g;
  EXPECT_NEAR(e.evaluate(to_um(m), g), 0.0, 1e-10);   // round-off of ~10^3 terms of order 1
  EXPECT_LT(g.cwiseAbs().maxCoeff(), 1e-9);
}

namespace {

/// The analytic gradient of `moduli`'s energy on the 66-vertex cell, noised by 0.1 um (on ~1.4 um edges: large,
/// nonlinear strains) and stretched by `stretch` along `axis`, against central differences at every `stride`-th vertex.
void expect_gradient_matches_central_differences(const EnergyModuli& moduli, unsigned seed, int axis, double stretch,
                                                 int stride) {
  const TriangleMesh m = make_rbc_mesh({.vertex_count = 66});
  const Positions rest = to_um(m);
  MembraneEnergy e(rest, m.triangles, moduli);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1);
  Positions x = rest;
  for (int i = 0; i < x.rows(); ++i)
    for (int k = 0; k < 3; ++k) x(i, k) += noise(rng);
  x.col(axis) *= stretch;
  Positions g, scratch;
  e.evaluate(x, g);
  const double step = 1e-6;
  for (int i = 0; i < x.rows(); i += stride) {
    for (int k = 0; k < 3; ++k) {
      Positions xp = x, xm = x;
      xp(i, k) += step;
      xm(i, k) -= step;
      const double fd = (e.evaluate(xp, scratch) - e.evaluate(xm, scratch)) / (2.0 * step);
      // central difference error ~ step^2 * E''' plus round-off E/step * 1e-16: 1e-5 relative to the force scale
      EXPECT_NEAR(g(i, k), fd, 1e-5 * (1.0 + std::abs(fd))) << "vertex " << i << " component " << k;
    }
  }
}

}  // namespace

TEST(MembraneEnergy, GradientMatchesCentralDifferences) {
  expect_gradient_matches_central_differences(all_terms(), 42, 0, 1.2, 7);   // a 20% stretch: the hardening matters
}

// The in-plane shear law against Skalak, Tozeren, Zarda & Chien 1973 (Biophys J 13:245):
//   W_S = (G/4) (I1^2 + 2 I1 - 2 I2) + (C G/4) I2^2,  I1 = s1^2 + s2^2 - 2,  I2 = s1^2 s2^2 - 1,
// written out here from the paper, not from the code. The model's lambda-part (A0/2) sum_i [(lambda/8) s_i^4 -
// (lambda/4) s_i^2] minus its rest value is (lambda/16) sum_i (s_i^2 - 1)^2 = (lambda/16)(I1^2 + 2 I1 - 2 I2): Skalak
// with G = lambda/4 and C = 0 (area is the separate PD term). The hardening part adds (mu/8) sum_i (s_i - 1)^4.
// Every deformation below keeps the area (s1 s2 = 1), so the area term is zero and the stretches are known exactly.
TEST(MembraneEnergy, FlatTriangleInPureShearIsSkalak1973ToRoundOff) {
  const double g_s = 2.5;   // pN/um, the default G_s = 2.5 uN/m
  const double mu_h = 0.75 * 4.0 * g_s;
  const double eps = 0.2;   // finite strain: the exact law, not its small-strain limit
  const double s1 = 1.0 + eps, s2 = 1.0 / (1.0 + eps);
  const double i1 = s1 * s1 + s2 * s2 - 2.0;
  const double skalak = 0.25 * g_s * (i1 * i1 + 2.0 * i1);   // I2 = 0
  const double hardening = 0.125 * mu_h * (std::pow(s1 - 1.0, 4) + std::pow(s2 - 1.0, 4));
  // A scalene triangle in a tilted plane, sheared along in-plane axes a, b at an angle to its edges.
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::UnitX()).normalized(), t2 = n.cross(t1);
  const Eigen::Vector3d a = std::cos(0.7) * t1 + std::sin(0.7) * t2, b = n.cross(a);
  const Positions rest = flat_triangle(t1, t2, 1.3);
  Positions x = rest;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d p = rest.row(i).transpose();
    x.row(i) = (p + eps * p.dot(a) * a + (1.0 / (1.0 + eps) - 1.0) * p.dot(b) * b).transpose() + Eigen::RowVector3d(2, -1, 5);
  }
  MembraneEnergy e(rest, {{0, 1, 2}}, {.skalak_lambda_pN_um = 4.0 * g_s, .hardening_mu_pN_um = mu_h,
                                       .area_weight_pN_um = 5000.0, .bending_pN_um = 0.2});
  Positions g;
  const double a0 = e.rest_area();
  // Round-off: ~20 operations on O(lambda) terms whose difference is O(lambda eps^2): 1e-13 relative.
  const double ratio = e.evaluate(x, g) / (a0 * (skalak + hardening));
  EXPECT_NEAR(ratio, 1.0, 1e-12);
  std::printf("pure shear eps = %.1f: E / (A0 W_Skalak) - 1 = %.2e\n", eps, ratio - 1.0);
  // No net force on an isolated element (translation invariance).
  EXPECT_LT(g.colwise().sum().norm(), 1e-12 * g.norm());
}

namespace {

/// A flat patch in pure shear (e_xx = eps, e_yy = -eps): its energy over the linear law 2 G eps^2 A, G = 2.5 pN/um, for a
/// membrane whose Skalak modulus is `modulus_factor` x 4 G.
double small_pure_shear_over_linear_law(double eps, double modulus_factor) {
  const double g_s = 2.5;
  const Positions rest = flat_patch(6);
  Positions x = rest;
  x.col(0) *= 1.0 + eps;
  x.col(1) /= 1.0 + eps;
  MembraneEnergy e(rest, patch_triangles(6), {.skalak_lambda_pN_um = modulus_factor * 4.0 * g_s, .area_weight_pN_um = 5000.0});
  Positions g;
  return e.evaluate(x, g) / (2.0 * g_s * eps * eps * e.rest_area());
}

}  // namespace

TEST(MembraneEnergy, SmallPureShearOfAFlatPatchIsTwoGEpsSquaredA) {
  // Linear elasticity: in pure shear (e_xx = eps, e_yy = -eps) the energy per area is G (e_xx^2 + e_yy^2) = 2 G eps^2.
  // The exact Skalak value above is 2 G eps^2 (1 - eps + O(eps^2)) for s1 = 1 + eps, s2 = 1/(1 + eps); at eps = 1e-4
  // the band 1.5 eps holds that term, and round-off (cancellation of O(1) terms, 1e-16 / eps^2 = 1e-8) is far below.
  // A modulus more than 0.03% low fails. Every triangle of a flat patch sees the same stretches: the sum is exact too.
  const double eps = 1e-4;
  const double ratio = small_pure_shear_over_linear_law(eps, 1.0);
  EXPECT_NEAR(ratio, 1.0, 1.5 * eps);
  std::printf("pure shear eps = %.0e: E / (2 G eps^2 A) - 1 = %.3e (leading term -eps)\n", eps, ratio - 1.0);
}

TEST(MembraneEnergy, NegativeControlAModulusOnePerMilleLowFailsTheSmallStrainBand) {
  // The band of the test above (1.5 eps = 1.5e-4) must see a modulus 0.1% low: the ratio is then 0.999 (1 - eps).
  const double eps = 1e-4;
  EXPECT_GT(std::abs(small_pure_shear_over_linear_law(eps, 0.999) - 1.0), 1.5 * eps);
}

TEST(MembraneEnergy, SimpleShearOfAFlatPatchIsSkalak1973) {
  // x -> x + gamma y: C = [[1, gamma], [gamma, 1 + gamma^2]], I1 = gamma^2, I2 = 0, so W_S = (G/4)(gamma^4 + 2 gamma^2)
  // (small strain: G gamma^2 / 2, the linear-elastic 2 G e_xy^2 with e_xy = gamma/2). The principal axes turn with
  // gamma, unlike pure shear along the axes. Round-off as in the triangle test.
  const double g_s = 2.5;
  const double gamma = 0.3;
  const Positions rest = flat_patch(6);
  Positions x = rest;
  x.col(0) += gamma * rest.col(1);
  MembraneEnergy e(rest, patch_triangles(6), {.skalak_lambda_pN_um = 4.0 * g_s, .area_weight_pN_um = 5000.0});
  Positions g;
  const double skalak = 0.25 * g_s * (std::pow(gamma, 4) + 2.0 * gamma * gamma);
  const double ratio = e.evaluate(x, g) / (skalak * e.rest_area());
  EXPECT_NEAR(ratio, 1.0, 1e-12);
  std::printf("simple shear gamma = %.1f: E / (A W_Skalak) - 1 = %.2e\n", gamma, ratio - 1.0);
}

namespace {

/// E_b / (8 pi k_c) - 1 for a sphere of radius 2 um at rest as 1 um, on the icosphere of `vertices`.
double helfrich_sphere_excess(int vertices) {
  // Rest sphere R = 1 um, current sphere R = 2 um: |K x| doubles on every hinge, so E_b = (k_c/2) sum w |K x_rest|^2,
  // which the Helfrich energy (k_c/2) integral (2H)^2 dA = 8 pi k_c should match as the mesh is refined.
  const TriangleMesh s = make_sphere_mesh(vertices);
  const Positions rest = to_um(s) * 1e-6;   // make_sphere_mesh is the unit sphere; read as 1 um
  const double kc = 0.2;
  MembraneEnergy e(rest, s.triangles, {.skalak_lambda_pN_um = 0.0, .hardening_mu_pN_um = 0.0, .area_weight_pN_um = 0.0,
                                       .bending_pN_um = kc, .volume_modulus_pN_um2 = 0.0, .global_area_pN_um = 0.0});
  Positions g;
  return e.evaluate(rest * 2.0, g) / (8.0 * std::numbers::pi * kc) - 1.0;
}

}  // namespace

TEST(MembraneEnergy, BendingOfASphereIsMeshIndependentAndNearHelfrich) {
  // Measured this way (session 13): the excess over Helfrich's 8 pi k_c does NOT fall with refinement: +1.62% (162),
  // +1.50% (642), +1.51% (2562). It is a constant offset of the discrete hinge energy (likely its area weights), not a
  // discretisation error: the bending modulus acts ~1.5% high at every resolution. Asserted: the offset is converged
  // (642 vs 2562 within 0.2 points, so the 258/642-vertex cells see the same k_c) and stays under 2% of Helfrich, the
  // measured bending moduli of RBC membranes spreading far wider than that (a factor of ~2 between methods).
  const double e642 = helfrich_sphere_excess(642);
  const double e2562 = helfrich_sphere_excess(2562);
  std::printf("Helfrich sphere: E / 8 pi k_c - 1 = %.3e (642), %.3e (2562)\n", e642, e2562);
  EXPECT_LT(std::abs(e2562 - e642), 0.002);
  EXPECT_LT(std::abs(e2562), 0.02);
}

// The neo-Hookean law of the capsule benchmarks (Barthes-Biesel & Rallison 1981; Ramanujan & Pozrikidis 1998):
// W = (G/2) (s1^2 + s2^2 + 1/(s1 s2)^2 - 3), written out here from those papers. Unlike the deformations above, these
// change the area, which the law must resist by itself (no penalty term is added).
TEST(MembraneEnergy, NeoHookeanFlatPatchMatchesItsLawInAreaChangingStretch) {
  const double g_s = 2.5;
  const Positions rest = flat_patch(6);
  MembraneEnergy e(rest, patch_triangles(6), {.law = InPlaneLaw::neo_hookean, .skalak_lambda_pN_um = 4.0 * g_s});
  Positions g;
  for (const auto& [s1, s2] : {std::pair{1.3, 1.0}, std::pair{1.2, 1.2}, std::pair{1.5, 0.8}, std::pair{0.9, 0.95}}) {
    Positions x = rest;
    x.col(0) *= s1;
    x.col(1) *= s2;
    const double law = 0.5 * g_s * (s1 * s1 + s2 * s2 + 1.0 / (s1 * s1 * s2 * s2) - 3.0);
    // Round-off of a few dozen operations on O(G) terms: 1e-12 relative.
    EXPECT_NEAR(e.evaluate(x, g) / (e.rest_area() * law), 1.0, 1e-12) << "stretches " << s1 << ", " << s2;
  }
}

TEST(MembraneEnergy, NeoHookeanSmallStrainModuliAreGAndThreeG) {
  // Linear limit of the neo-Hookean law: W = G (e1^2 + e2^2) + G (e1 + e2)^2, i.e. shear modulus G and area modulus
  // K = 3 G (surface Poisson ratio 1/2): equibiaxial e1 = e2 = eps gives W = 2 K eps^2 = 6 G eps^2 (the area-
  // changing mode the capsule's linear deformation D = (25/12) Ca_G depends on), pure shear 2 G eps^2. At eps = 1e-4
  // the O(eps) correction is held by a band of 5 eps (the equibiaxial cubic term is -4 eps relative); round-off 1e-8.
  const double g_s = 2.5, eps = 1e-4;
  const Positions rest = flat_patch(6);
  MembraneEnergy e(rest, patch_triangles(6), {.law = InPlaneLaw::neo_hookean, .skalak_lambda_pN_um = 4.0 * g_s});
  Positions g, x = rest;
  x *= 1.0 + eps;
  EXPECT_NEAR(e.evaluate(x, g) / (6.0 * g_s * eps * eps * e.rest_area()), 1.0, 5.0 * eps);
  x = rest;
  x.col(0) *= 1.0 + eps;
  x.col(1) /= 1.0 + eps;
  EXPECT_NEAR(e.evaluate(x, g) / (2.0 * g_s * eps * eps * e.rest_area()), 1.0, 5.0 * eps);
}

TEST(MembraneEnergy, NeoHookeanGradientMatchesCentralDifferences) {
  EnergyModuli moduli = all_terms();
  moduli.law = InPlaneLaw::neo_hookean;
  expect_gradient_matches_central_differences(moduli, 7, 1, 1.3, 5);   // a 30% area-changing stretch
}
