// SPDX-License-Identifier: MIT
// How the immersed boundary's slip depends on the lattice's tau: a periodic array of fixed spheres (markers, 5
// multi-direct forcing iterations, as the shear cases) pushed through by a body force, its steady permeability U nu / g
// at tau 0.8 to 8. Most of it is Lambda = (tau+ - 1/2)(tau- - 1/2) (Seta et al. 2014, PRE 89:023307: the odd relaxation
// time sets the IB-LBM's slip): TRT holds Lambda at 3/16 at every tau, the regularised collision's default odd bound
// lets it grow (0.42 at tau 8). docs/resolved-coupling.md, "The lattice's tau is Lambda".
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ibm_test_helpers.hpp"
#include "resolved/ibm/immersed_boundary.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

double mean_velocity_x(const FluidLattice& lattice) {
  const auto& n = lattice.layout().n;
  double s[2] = {0.0, 0.0};
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const NodeMoments m = lattice.moments(x, y, z);
        s[0] += m.rho * m.u.x;
        s[1] += m.rho;
      }
  MPI_Allreduce(MPI_IN_PLACE, s, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return s[0] / s[1];
}

/// The steady permeability U nu / g of a 16^3 periodic cell holding one sphere of radius 3 lu (2.8 % solid), the
/// body force g chosen so that U ~ 7e-4 lu at every tau (the same Mach number; Re = U a / nu <= 0.02).
double permeability(CollisionParams collision) {
  const int n = 16;
  FluidLattice lattice(LatticeSpec{.global_nodes = {n, n, n}, .periodic = {true, true, true}, .collision = collision},
                       MPI_COMM_WORLD);
  lattice.enable_force_field();
  lattice.initialize([](const Vec3&) { return NodeInit{.rho_lu = 1.0, .u_lu = {}}; });
  const double nu = collision.viscosity_lu();
  const double g = 2.0e-5 * nu;
  lattice.set_body_force({g, 0.0, 0.0});
  const Markers sphere = sphere_markers({7.6, 8.1, 7.9}, 3.0, 120);
  ImmersedBoundary ibm(lattice, {.kernel = DeltaKernel::two_point, .iterations = 5, .measure_slip = false});
  // The slowest mode decays as exp(-nu (2 pi / n)^2 t): 160 of its times (at 40, k moved by < 2e-3; at 160 and 640
  // the same to 1e-5, measured).
  const long steps = std::lround(160.0 * n * n / (4.0 * std::numbers::pi * std::numbers::pi * nu));
  for (long s = 0; s < steps; ++s) {
    ibm.apply(sphere);
    lattice.step();
  }
  ibm.apply(sphere);   // the force field of the state measured (moments() include half of it)
  return mean_velocity_x(lattice) * nu / g;
}

CollisionParams trt(double tau) { return {.model = CollisionModel::trt, .tau = tau}; }
CollisionParams regularized(double tau, double odd_rate_max) {
  return {.model = CollisionModel::regularized, .tau = tau, .odd_rate_max = odd_rate_max};
}

TEST(ImmersedBoundarySlip, FollowsLambdaNotTau) {
  const double k_08 = permeability(trt(0.8));
  const double k_2 = permeability(trt(2.0));
  const double k_8 = permeability(trt(8.0));
  const double k_reg = permeability(regularized(8.0, regularized_odd_rate_max_default));   // Lambda 0.42
  const double k_reg_kept = permeability(regularized(8.0, 1.99));                         // Lambda 3/16
  std::printf("[ibm slip] permeability U nu / g: TRT tau 0.8 %.6f, 2 %.6f, 8 %.6f; regularised tau 8 (Lambda %.3f) "
              "%.6f, with odd_rate_max 1.99 (Lambda %.4f) %.6f\n",
              k_08, k_2, k_8, regularized(8.0, 1.8).bulk_lambda(), k_reg, regularized(8.0, 1.99).bulk_lambda(),
              k_reg_kept);
  // Measured: TRT +1.6 % at tau 2 and +3.2 % at tau 8 against tau 0.8 (at fixed Lambda a residual that more
  // forcing iterations do not remove: +2.8 % at 20), the default bound at tau 8 +11.7 %, the bound raised to 1.99
  // (Lambda 3/16, even part regularised) +4.5 %. Asserted with ~1 point of margin: a fixed-Lambda collision stays
  // within 4.5 % over tau 0.8-8, and the default bound's growing Lambda slips at least 5 % more than TRT at tau 8.
  EXPECT_NEAR(k_2 / k_08, 1.0, 0.025);
  EXPECT_NEAR(k_8 / k_08, 1.0, 0.045);
  EXPECT_NEAR(k_reg_kept / k_08, 1.0, 0.055);
  EXPECT_GT(k_reg / k_8, 1.05);
}

}  // namespace
}  // namespace hs::resolved
