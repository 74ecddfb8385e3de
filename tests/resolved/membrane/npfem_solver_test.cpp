// SPDX-License-Identifier: MIT
// The npFEM solver: rest state without creep, Newton's second law for a rigid push, centre constraints, PD fallback
// vs L-BFGS, a bit-for-bit checkpoint round trip, a non-finite force refused and an unreachable one reported, a
// line search lost in round-off counted as converged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "resolved/membrane/npfem_solver.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

using namespace hs::resolved;
using hs::common::Vec3;

namespace {

constexpr double lb_step_s = 0.25e-6;   // Palabos-npFEM membrane step: 2 LB steps of 0.125 us (reference §2.3)

double max_distance_m(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, norm(a[i] - b[i]));
  return d;
}

}  // namespace

TEST(NpfemSolver, RestStateWithoutLoadDoesNotCreepOverTenThousandSteps) {
  const TriangleMesh mesh = make_rbc_mesh({});
  NpfemSolver solver(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  for (int s = 0; s < 10000; ++s) (void)solver.step();
  const auto x = solver.positions_m();
  // Acceptance of issue 3: max displacement < 1% of D0, area and volume drift < 0.1%.
  EXPECT_LT(max_distance_m(x, mesh.vertices_m), 0.01 * 7.82e-6);
  EXPECT_LT(std::abs(solver.area_m2() / solver.rest_area_m2() - 1.0), 1e-3);
  EXPECT_LT(std::abs(solver.volume_m3() / solver.rest_volume_m3() - 1.0), 1e-3);
  EXPECT_EQ(solver.statistics().unconverged_steps, 0);
}

TEST(NpfemSolver, SqueezedCellReturnsToItsRestShape) {
  const TriangleMesh mesh = make_rbc_mesh({});
  MembraneParameters material;
  material.deformation_friction_Pa_s_m = 0.0;   // quasi-static: long steps reach each equilibrium in a few steps
  NpfemSettings settings;
  settings.max_iterations = 300;
  NpfemSolver solver(mesh, material, settings, 1e-5);
  // A gentle radial squeeze (0.03 pN per um of radius on every vertex: about 0.1 um deformation), then released.
  std::vector<Vec3> f(mesh.vertices_m.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = Vec3{-mesh.vertices_m[i].x, -mesh.vertices_m[i].y, 0.0} * (0.03e-12 / 1e-6);
  solver.set_external_forces_N(f);
  for (int s = 0; s < 30; ++s) (void)solver.step();
  const double squeezed = max_distance_m(solver.positions_m(), mesh.vertices_m);
  EXPECT_GT(squeezed, 0.02e-6);
  solver.clear_external_forces();
  for (int s = 0; s < 60; ++s) (void)solver.step();
  const Vec3 c = solver.centroid_m();
  std::vector<Vec3> centred = solver.positions_m();
  for (auto& p : centred) p -= c;
  // Elastic: the unloaded equilibrium is the rest shape; 1% of the squeeze is the solver tolerance level.
  EXPECT_LT(max_distance_m(centred, mesh.vertices_m), 0.01 * squeezed);
}

TEST(NpfemSolver, UniformForceAcceleratesTheCellAsARigidBody) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  NpfemSolver solver(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  const double f_vertex_N = 1e-13;
  solver.set_external_forces_N(std::vector<Vec3>(mesh.vertices_m.size(), Vec3{f_vertex_N, 0.0, 0.0}));
  const Vec3 c0 = solver.centroid_m();
  (void)solver.step();
  // Implicit Euler on a rigid translation (L 1 = 0, damping and elastic forces vanish): dx = h^2 f / m.
  const double expected = lb_step_s * lb_step_s * f_vertex_N / solver.vertex_mass_kg();
  EXPECT_NEAR((solver.centroid_m() - c0).x / expected, 1.0, 1e-9);
  EXPECT_NEAR(solver.velocities_m_s()[0].x / (expected / lb_step_s), 1.0, 1e-9);
}

TEST(NpfemSolver, DefaultFrictionIsPalabosVelocityRelaxationAtItsOwnStep) {
  const TriangleMesh mesh = make_rbc_mesh({});
  const MembraneParameters material;
  const NpfemSolver solver(mesh, material, NpfemSettings{}, lb_step_s);
  // The definition: C = zeta h / (zeta h + m) with zeta = zeta_A A / n.
  const double zeta_h = material.deformation_friction_Pa_s_m * solver.rest_area_m2() /
                        static_cast<double>(mesh.vertices_m.size()) * lb_step_s;
  EXPECT_NEAR(solver.velocity_relaxation(), zeta_h / (zeta_h + solver.vertex_mass_kg()), 1e-14);
  // The calibration: Palabos-npFEM's C_alpha = 0.9 at h = 0.25 us and physical density (reference §3.3); 0.002
  // allows the 3-digit default and the generated mesh's V / A differing from the 0.697 um used to state it.
  EXPECT_NEAR(solver.velocity_relaxation(), 0.9, 2e-3);
}

TEST(NpfemSolver, DeformationRateDoesNotDependOnStepOrMassScaling) {
  // The same squeeze for 0.5 ms, marched with (h, mass) = (0.25 us, x1) and (2 us, x20): h / m is 2.5x smaller in the
  // second, and with a fixed per-step C_alpha = 0.9 it deformed 2.5x less (ratio 0.40 measured). A friction per time
  // and area must give the same deformation.
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  auto squeezed_after = [&](double h_s, double mass_factor) {
    MembraneParameters material;
    material.density_kg_m3 *= mass_factor;
    NpfemSettings settings;
    settings.max_iterations = 200;   // converged steps: only the time discretisation differs
    NpfemSolver solver(mesh, material, settings, h_s);
    std::vector<Vec3> f(mesh.vertices_m.size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = Vec3{-mesh.vertices_m[i].x, 0.0, 0.0} * (3e-12 / 1e-6);
    solver.set_external_forces_N(f);
    const int steps = static_cast<int>(std::lround(0.5e-3 / h_s));
    for (int s = 0; s < steps; ++s) (void)solver.step();
    return max_distance_m(solver.positions_m(), mesh.vertices_m);
  };
  const double fine = squeezed_after(lb_step_s, 1.0);
  const double coarse = squeezed_after(8.0 * lb_step_s, 20.0);
  EXPECT_GT(fine, 0.02e-6);   // a real deformation, far from the 1e-4 solver tolerance
  // Backward Euler at h = 2 us on a relaxation of ~ms: O(h / t) ~ 1e-3; the inertial times m / zeta (< 1 us) differ
  // but are far below the 0.5 ms observed. 2 % bounds both with margin, and excludes the 2.5x of a per-step rule.
  EXPECT_NEAR(coarse / fine, 1.0, 0.02);
}

TEST(NpfemSolver, CentreConstraintsHoldTheCell) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  NpfemSolver solver(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  solver.set_external_forces_N(std::vector<Vec3>(mesh.vertices_m.size(), Vec3{1e-13, 2e-13, 0.0}));
  solver.set_center_constraint(CenterConstraint::fixed);
  for (int s = 0; s < 10; ++s) (void)solver.step();
  EXPECT_LT(norm(solver.centroid_m()), 1e-18);   // held at the origin to round-off
  solver.set_center_constraint(CenterConstraint::axis, {1.0, 0.0, 0.0});
  for (int s = 0; s < 10; ++s) (void)solver.step();
  EXPECT_GT(solver.centroid_m().x, 0.0);           // free along the axis
  EXPECT_LT(std::abs(solver.centroid_m().y), 1e-18);
}

TEST(NpfemSolver, ProjectiveDynamicsFallbackReachesTheSameState) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  std::vector<Vec3> f(mesh.vertices_m.size());
  const auto ends = std::minmax_element(mesh.vertices_m.begin(), mesh.vertices_m.end(),
                                        [](const Vec3& a, const Vec3& b) { return a.x < b.x; });
  f[ends.first - mesh.vertices_m.begin()] = Vec3{-20e-12, 0.0, 0.0};
  f[ends.second - mesh.vertices_m.begin()] = Vec3{20e-12, 0.0, 0.0};
  NpfemSettings lbfgs;
  lbfgs.max_iterations = 2000;
  NpfemSettings pd = lbfgs;
  pd.iteration = NpfemIteration::projective_dynamics;
  pd.max_iterations = 20000;
  MembraneParameters material;
  material.deformation_friction_Pa_s_m = 0.0;
  NpfemSolver a(mesh, material, lbfgs, 1e-6);   // 1 us: the inertia term keeps PD's iteration count moderate
  NpfemSolver b(mesh, material, pd, 1e-6);
  a.set_external_forces_N(f);
  b.set_external_forces_N(f);
  for (int s = 0; s < 5; ++s) {
    const auto ra = a.step();
    const auto rb = b.step();
    EXPECT_TRUE(ra.converged) << ra.stop_reason;
    EXPECT_TRUE(rb.converged) << rb.stop_reason;
  }
  // Same minimiser: agree to 0.1 nm (both stop at a residual of 1e-4 of the vertex force scale; measured 3 pm).
  EXPECT_LT(max_distance_m(a.positions_m(), b.positions_m()), 1e-10);
  EXPECT_LT(a.statistics().iterations, b.statistics().iterations);   // quasi-Newton needs fewer iterations
}

TEST(NpfemSolver, NonFiniteForceIsAnErrorAndAnUnreachableForceAnUnconvergedStep) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  NpfemSolver solver(mesh, MembraneParameters{}, NpfemSettings{}, 1e-3);
  std::vector<Vec3> f(mesh.vertices_m.size());
  f[3] = Vec3{std::nan(""), 0.0, 0.0};   // what a broken coupling would hand over
  EXPECT_THROW(solver.set_external_forces_N(f), hs::common::NumericalError);
  // One newton on one vertex, 10^10 times the experiment's forces, at h = 1 ms. What the solver does (measured when
  // this test was made decisive; it used to accept a throw or survival alike): from the rest state the quasi-Newton
  // step towards the force is so long that the nonlinear energy rises at every one of the 5 halvings, so the line
  // search stops at its first iteration and the step ends unconverged where it started. It must say so, every step:
  // not converged, stop reason "line_search", and the gradient it reports is the unbalanced external force, exactly
  // 1 N (at the rest shape the elastic forces vanish and the inertial term M~ (x_n - y) / h^2 is -f_ext), counted in
  // the statistics the run summary writes (cell_simulation.cpp). No exception, no NaN.
  f[3] = Vec3{1.0, 0.0, 0.0};
  solver.set_external_forces_N(f);
  for (int s = 0; s < 10; ++s) {
    const NpfemStepReport r = solver.step();
    EXPECT_FALSE(r.converged) << "step " << s;
    EXPECT_EQ(r.stop_reason, "line_search") << "step " << s;
    EXPECT_NEAR(r.gradient_max_N, 1.0, 1e-6) << "step " << s;
  }
  EXPECT_EQ(solver.statistics().unconverged_steps, 10);
  EXPECT_EQ(solver.statistics().line_search_stops, 10);
  for (const auto& p : solver.positions_m()) {
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
}

TEST(NpfemSolver, RestoredStateContinuesBitForBit) {
  // The state holds the start predictor and the L-BFGS pairs, so a restored solver repeats the original exactly.
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  std::vector<Vec3> f(mesh.vertices_m.size());
  f[0] = Vec3{20e-12, 5e-12, 0.0};
  f[5] = Vec3{-20e-12, 0.0, 3e-12};
  NpfemSolver a(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  a.set_external_forces_N(f);
  for (int s = 0; s < 20; ++s) (void)a.step();
  NpfemSolver b(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  b.restore_state(a.state());
  for (int s = 0; s < 20; ++s) {
    const auto ra = a.step();
    const auto rb = b.step();
    EXPECT_EQ(ra.iterations, rb.iterations);
  }
  EXPECT_EQ(max_distance_m(a.positions_m(), b.positions_m()), 0.0);
  // A state without the solver memory (positions, velocities, forces, centre target only) is still accepted.
  std::vector<double> bare = a.state();
  bare.resize(9 * mesh.vertices_m.size() + 3);
  NpfemSolver c(mesh, MembraneParameters{}, NpfemSettings{}, lb_step_s);
  EXPECT_NO_THROW(c.restore_state(bare));
  EXPECT_EQ(max_distance_m(a.positions_m(), c.positions_m()), 0.0);
}

TEST(NpfemSolver, ALineSearchLostInTheObjectivesRoundOffIsAConvergedStep) {
  // The shear case at Ca 11.7 in miniature: a viscous membrane (its 2.48e-8 N s/m), mass factor 100, an npFEM step
  // every 0.48 us and 100 pN of rotational load at the rim. Before descent_below_round_off, 19 of these 400 steps
  // ended "line_search", unconverged, with the gradient 1-5x its tolerance: the predicted decrease was ~1e-14 of the
  // objective, below what the objective resolves. The same steps now end "objective" (converged) at the same
  // positions; the 1 N push above, which a line search cannot follow for want of descent, stays unconverged.
  const TriangleMesh mesh = make_rbc_mesh({});
  MembraneParameters m;
  m.density_kg_m3 *= 100.0;
  m.deformation_friction_Pa_s_m = 0.0;
  m.viscosity_N_s_m = 2.483e-8;
  NpfemSolver solver(mesh, m, NpfemSettings{}, 0.48e-6);
  std::vector<Vec3> f(mesh.vertices_m.size());
  const double load_N = 1e-10;
  const double a_m = 3.91e-6;
  for (std::size_t i = 0; i < f.size(); ++i) {
    f[i] = Vec3{load_N * mesh.vertices_m[i].y / a_m, -load_N * mesh.vertices_m[i].x / a_m, 0.0};
  }
  solver.set_external_forces_N(f);
  double largest_gradient_at_tolerance_N = 0.0;
  double largest_gradient_at_round_off_N = 0.0;
  for (int s = 0; s < 400; ++s) {
    const NpfemStepReport r = solver.step();
    ASSERT_TRUE(r.converged) << "step " << s << ": " << r.stop_reason;
    double& largest = r.stop_reason == "gradient" ? largest_gradient_at_tolerance_N : largest_gradient_at_round_off_N;
    largest = std::max(largest, r.gradient_max_N);
  }
  EXPECT_EQ(solver.statistics().unconverged_steps, 0);
  EXPECT_EQ(solver.statistics().line_search_stops, 0);
  // Steps did end at the round-off floor with the gradient still above its tolerance (which every "gradient" stop
  // is under): the case this rule is for was exercised.
  EXPECT_GT(largest_gradient_at_round_off_N, largest_gradient_at_tolerance_N);
}
