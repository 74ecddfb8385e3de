// SPDX-License-Identifier: MIT
// Membrane viscosity (Kelvin-Voigt): 2 eta |D_dev|^2 A under a uniform in-plane rate of strain, nothing for rigid
// motion at any orientation, forces that conserve momentum, and the relaxation of a released cell with t = eta / G_s
// whose released elastic energy the viscosity dissipates (with backward Euler's own share).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include "resolved/membrane/membrane_parameters.hpp"
#include "resolved/membrane/membrane_viscosity.hpp"
#include "resolved/membrane/npfem_solver.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

using namespace hs::resolved;

namespace {

constexpr double eta = 0.7;   // any units: the class is linear in eta and in v

/// A 3 x 3 grid of points in the plane spanned by the orthonormal a, b (through p0), 8 triangles, 2 um squares.
struct Sheet {
  Positions x;
  std::vector<std::array<int, 3>> triangles;
  double area = 0.0;
};

Sheet tilted_sheet(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& p0) {
  Sheet s;
  s.x.resize(9, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.x.row(3 * i + j) = (p0 + 2.0 * i * a + (2.0 * j + 0.3 * i) * b).transpose();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int v = 3 * i + j;
      s.triangles.push_back({v, v + 3, v + 4});
      s.triangles.push_back({v, v + 4, v + 1});
    }
  s.area = 16.0;   // 4 x 4 um, a sheared grid keeps its area
  return s;
}

Eigen::Matrix3d rotation(double angle, Eigen::Vector3d axis) { return Eigen::AngleAxisd(angle, axis.normalized()).matrix(); }

Positions rbc_positions(const TriangleMesh& mesh) {
  Positions x(static_cast<Eigen::Index>(mesh.vertices_m.size()), 3);
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    const auto& p = mesh.vertices_m[i];
    x.row(static_cast<Eigen::Index>(i)) << p.x * 1e6, p.y * 1e6, p.z * 1e6;
  }
  return x;
}

}  // namespace

TEST(MembraneViscosity, UniformInPlaneRateOfStrainDissipatesTwoEtaDdevSquaredArea) {
  const Eigen::Matrix3d q = rotation(0.9, {1.0, -2.0, 0.5});   // a sheet at a general orientation
  const Eigen::Vector3d a = q.col(0), b = q.col(1), p0{3.0, -1.0, 2.0};
  Sheet s = tilted_sheet(a, b, p0);
  MembraneViscosity visc(s.triangles, eta);
  visc.freeze(s.x);
  // v = u0 + (D_ab in the (a, b) frame) applied to x - p0, plus a normal velocity that is uniform (a translation).
  const double d_aa = 0.8, d_ab = -0.35, d_bb = 0.2;   // with a trace: only D_dev dissipates
  const Eigen::Vector3d n = a.cross(b);
  Positions v(9, 3);
  for (int k = 0; k < 9; ++k) {
    const Eigen::Vector3d r = s.x.row(k).transpose() - p0;
    const double ra = r.dot(a), rb = r.dot(b);
    v.row(k) = ((d_aa * ra + d_ab * rb) * a + (d_ab * ra + d_bb * rb) * b + 0.4 * n + Eigen::Vector3d{1, 2, 3}).transpose();
  }
  Positions grad = Positions::Zero(9, 3);
  const double r = visc.rayleigh(v, grad);
  const double half = 0.5 * (d_aa - d_bb);
  const double ddev2 = 2.0 * half * half + 2.0 * d_ab * d_ab;   // |D_dev|^2 (Frobenius)
  // Dissipation 2 R against 2 eta |D_dev|^2 A: exact for a linear field on linear triangles, so round-off (1e-13).
  EXPECT_NEAR(2.0 * r / (2.0 * eta * ddev2 * s.area), 1.0, 1e-13);
  // The gradient is R's: v . dR/dv = 2 R (R is quadratic, Euler), to round-off.
  EXPECT_NEAR((v.array() * grad.array()).sum() / (2.0 * r), 1.0, 1e-13);
  // Pure shear (trace-free): the same with D_dev = D, for each triangle too.
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Eigen::Matrix2d d = visc.rate_of_strain(v, t);
    EXPECT_NEAR(d.trace(), d_aa + d_bb, 1e-13);
    EXPECT_NEAR(d.squaredNorm(), d_aa * d_aa + d_bb * d_bb + 2.0 * d_ab * d_ab, 1e-13);
  }
}

TEST(MembraneViscosity, RigidMotionAtAnyOrientationDissipatesNothing) {
  const TriangleMesh mesh = make_rbc_mesh({});
  // The cell after a finite rotation about a tilted axis and a shift: the frozen geometry of a step mid-flight.
  const Eigen::Matrix3d q = rotation(2.1, {0.3, -1.0, 0.7});
  Positions x = rbc_positions(mesh);
  for (Eigen::Index i = 0; i < x.rows(); ++i) x.row(i) = (q * x.row(i).transpose() + Eigen::Vector3d{5, -2, 7}).transpose();
  MembraneViscosity visc(mesh.triangles, eta);
  visc.freeze(x);
  const Eigen::Vector3d omega{40.0, -25.0, 60.0};   // rad per time unit, about another tilted axis
  const Eigen::Vector3d u0{3.0, 1.0, -2.0};
  Positions v(x.rows(), 3);
  for (Eigen::Index i = 0; i < x.rows(); ++i) v.row(i) = (u0 + omega.cross(x.row(i).transpose())).transpose();
  Positions grad = Positions::Zero(x.rows(), 3);
  const double r = visc.rayleigh(v, grad);
  // Scale: the R of a shear of rate |omega| over the cell's area (~135 um^2): eta A |omega|^2 ~ 5e5. Rigid motion gives
  // D = antisymmetric part only, so R is round-off squared: (1e-15 relative)^2; 1e-20 of the scale allows ~1e-10
  // in D, far above round-off and far below any real strain rate.
  const double scale = eta * 135.0 * omega.squaredNorm();
  EXPECT_LT(std::abs(r) / scale, 1e-20);
  // The viscous forces vanish too: max |dR/dv| against eta |omega| l (edge ~1 um): round-off (1e-12).
  EXPECT_LT(grad.rowwise().norm().maxCoeff() / (eta * omega.norm()), 1e-12);
}

TEST(MembraneViscosity, InternalForcesConserveMomentumAndAngularMomentum) {
  const TriangleMesh mesh = make_rbc_mesh({});
  Positions x = rbc_positions(mesh);
  MembraneViscosity visc(mesh.triangles, eta);
  visc.freeze(x);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Positions v(x.rows(), 3);
  for (Eigen::Index i = 0; i < v.rows(); ++i) v.row(i) << u(rng), u(rng), u(rng);
  Positions grad = Positions::Zero(x.rows(), 3);
  (void)visc.rayleigh(v, grad);
  const double magnitude = grad.rowwise().norm().sum();
  // Each triangle's three forces sum to zero by construction (vertex 0 takes minus the other two): round-off, 1e-14.
  EXPECT_LT(grad.colwise().sum().norm() / magnitude, 1e-14);
  // Zero torque about the frozen positions (the viscous tension is symmetric): round-off relative to sum |x| |f|.
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  double torque_scale = 0.0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    torque += x.row(i).transpose().cross(grad.row(i).transpose());
    torque_scale += x.row(i).norm() * grad.row(i).norm();
  }
  EXPECT_LT(torque.norm() / torque_scale, 1e-14);
}

TEST(MembraneViscosity, HessianIsTheGradientsDerivative) {
  // R is quadratic at the frozen geometry, so its Hessian times any v is its gradient at v, to round-off; the implicit
  // step's proxy (ViscousStepProxy) is built from this Hessian.
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  Positions x = rbc_positions(mesh);
  const Eigen::Matrix3d q = rotation(0.8, {1.0, 1.0, -0.4});
  for (Eigen::Index i = 0; i < x.rows(); ++i) x.row(i) = (q * x.row(i).transpose()).transpose();
  MembraneViscosity visc(mesh.triangles, eta);
  visc.freeze(x);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Positions v(x.rows(), 3);
  for (Eigen::Index i = 0; i < v.rows(); ++i) v.row(i) << u(rng), u(rng), u(rng);
  Positions grad = Positions::Zero(x.rows(), 3);
  (void)visc.rayleigh(v, grad);
  std::vector<Eigen::Triplet<double>> trip;
  visc.append_hessian(1.0, trip);
  Eigen::SparseMatrix<double> h(3 * x.rows(), 3 * x.rows());
  h.setFromTriplets(trip.begin(), trip.end());
  Eigen::VectorXd vv(3 * x.rows());
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    for (int c = 0; c < 3; ++c) vv[3 * i + c] = v(i, c);
  const Eigen::VectorXd hv = h * vv;
  double err = 0.0;
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    for (int c = 0; c < 3; ++c) err = std::max(err, std::abs(hv[3 * i + c] - grad(i, c)));
  EXPECT_LT(err / grad.cwiseAbs().maxCoeff(), 1e-13);
  // Symmetric, as a Hessian must be.
  EXPECT_LT((Eigen::MatrixXd(h) - Eigen::MatrixXd(h).transpose()).cwiseAbs().maxCoeff() / Eigen::MatrixXd(h).cwiseAbs().maxCoeff(),
            1e-15);
}

namespace {

/// In-plane deformation of a disc, whatever its orientation: (l1 - l2) / (l1 + l2) with l1 >= l2 the two largest
/// eigenvalues of the vertex cloud's gyration tensor (the disc's plane).
double in_plane_deformation(const std::vector<hs::common::Vec3>& p) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& q : p) c += Eigen::Vector3d{q.x, q.y, q.z};
  c /= static_cast<double>(p.size());
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (const auto& q : p) {
    const Eigen::Vector3d r = Eigen::Vector3d{q.x, q.y, q.z} - c;
    g += r * r.transpose();
  }
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(g).eigenvalues();   // ascending
  return (l[2] - l[1]) / (l[2] + l[1]);
}

struct Relaxation {
  double time_s;       // fitted e-folding time of the deformation
  double released_J;   // elastic energy at release minus at the end
  double dissipated_J; // the viscosity's dissipation over the run (NpfemStatistics)
  double deformation0; // at release
  long iterations;
  long unconverged;
};

/// The cell stretched by 1 + eps along x and 1 / (1 + eps) along y (area and volume kept), released at rest, marched
/// with step h; the e-folding time of the deformation from a log-linear fit between 60 % and 10 % of it.
Relaxation relax(const MembraneParameters& material, double eps, double h_s, int steps) {
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  NpfemSettings settings;
  // converged steps: the time discretisation is what is measured
  settings.max_iterations = 200;
  NpfemSolver solver(mesh, material, settings, h_s);
  const double rest = in_plane_deformation(solver.positions_m());
  std::vector<double> state = solver.state();
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    state[3 * i] *= 1.0 + eps;
    state[3 * i + 1] /= 1.0 + eps;
  }
  solver.restore_state(state);
  const double d0 = in_plane_deformation(solver.positions_m()) - rest;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int n = 0;
  double e0 = 0.0, diss0 = 0.0;
  for (int s = 1; s <= steps; ++s) {
    (void)solver.step();
    if (s == 10) {   // after the fast, non-viscous adjustment of the release (see the energy check)
      e0 = solver.elastic_energy_J();
      diss0 = solver.statistics().viscous_dissipation_J;
    }
    const double d = (in_plane_deformation(solver.positions_m()) - rest) / d0;
    if (d < 0.6 && d > 0.1) {
      const double t = s * h_s, y = std::log(d);
      sx += t, sy += y, sxx += t * t, sxy += t * y, ++n;
    }
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {-1.0 / slope, e0 - solver.elastic_energy_J(), solver.statistics().viscous_dissipation_J - diss0, d0,
          solver.statistics().iterations, solver.statistics().unconverged_steps};
}

}  // namespace

TEST(MembraneViscosity, ReleasedCellRelaxesWithTheKelvinVoigtTime) {
  // Hochmuth et al. 1979's experiment in the model: a cell stretched by 1 % in its plane and released recovers as
  // exp(-t / t_c), t_c = eta_m / G_s (2 G_s eps_dev + 2 eta_m d eps_dev / dt = 0 on the flat faces). Backward Euler
  // with step h gives the e-folding time h / ln(1 + h / t_c). No fluid: the friction and the Rayleigh damping are off.
  // eta_m is the default / 100 (t_c = 2.8 ms instead of 0.28 s): the steps are then short enough for the vertex
  // inertia to hold the out-of-plane modes, which in a membrane without fluid only the bending resists; at t_c =
  // 0.28 s (steps of 5.6 ms, quasi-static) a 1-3 % stretch buckled the rim mid-relaxation (measured; 0.3 % did not,
  // -4.1 %). t_c is linear in eta_m (second run), so the scale is no loss.
  MembraneParameters material;
  material.deformation_friction_Pa_s_m = 0.0;
  material.rayleigh_beta_s = 0.0;
  material.viscosity_N_s_m = 0.01 * kMembraneViscosityHochmuth1979_N_s_m;
  const double t_c = material.viscosity_N_s_m / material.shear_modulus_N_m;   // 2.8 ms
  const double h = t_c / 50.0;
  const Relaxation r1 = relax(material, 0.01, h, 120);
  material.viscosity_N_s_m *= 2.0;
  const Relaxation r2 = relax(material, 0.01, 2.0 * h, 120);   // the same h / t_c
  const double expected = h / std::log1p(h / t_c);
  std::printf("t_c = eta_m / G_s = %.4g s, backward Euler %.4g s, measured %.4g s (%+.2f %%); 2 eta_m: x %.4f; "
              "%.1f L-BFGS iterations per step, %ld unconverged steps\n", t_c, expected, r1.time_s,
              100.0 * (r1.time_s / expected - 1.0), r2.time_s / r1.time_s, static_cast<double>(r1.iterations) / 120.0,
              r1.unconverged + r2.unconverged);
  std::printf("energy: released %.4g J, dissipated by the viscosity %.4g J (ratio %.4f)\n", r1.released_J,
              r1.dissipated_J, r1.dissipated_J / r1.released_J);
  // Measured -2.8 % (66 vertices; -2.3 % at 162, -3.2 % at 258): the cell is not a flat sheet, and the rim's
  // bending adds to the restoring force (at 258 vertices k_c / 10: -2.1 %, k_c x 10: -5.6 %). 5 % bounds that at the
  // default k_c; a viscosity off by a factor (a unit or a missing 2) fails it by far.
  EXPECT_NEAR(r1.time_s / expected, 1.0, 0.05);
  // Kelvin-Voigt: the time is eta_m over a stiffness, linear in eta_m. Measured x 2.0007 (258 vertices); 1 % allows
  // the inertia (m / eta_m ~ 1e-3 of t_c) and the fit.
  EXPECT_NEAR(r2.time_s / r1.time_s, 2.0, 0.02);
  EXPECT_EQ(r1.unconverged + r2.unconverged, 0);
  // Energy: from step 10 on (the release first sheds the rim's non-shear energy, ~95 % of it, through the inertial
  // modes, which only the implicit step damps) the elastic energy released goes into the viscous dissipation and
  // backward Euler's own loss. For a Kelvin-Voigt mode x_{n+1} = x_n / (1 + h / t), the step dissipates
  // (c / h) dx^2 = k (t / h) dx^2 while E drops by that plus k dx^2 / 2: the ratio is 1 / (1 + h / (2 t)).
  // Measured 0.9900 against 0.9901; 2e-3 allows the mode's t differing from t_c by 3 % (3e-4) and the fit-free rest.
  EXPECT_NEAR(r1.dissipated_J / r1.released_J, 1.0 / (1.0 + h / (2.0 * t_c)), 2e-3);
}

TEST(MembraneViscosity, RestoredViscousSolverContinuesBitForBit) {
  // The state holds the step proxy's age and geometry, so a resumed run refactorises where the original did and
  // repeats it exactly, also between refactorisations (every 3 steps here; resumed at step 7).
  const TriangleMesh mesh = make_rbc_mesh({.vertex_count = 66});
  MembraneParameters material;
  material.viscosity_N_s_m = kMembraneViscosityHochmuth1979_N_s_m;
  material.deformation_friction_Pa_s_m = 0.0;
  material.density_kg_m3 *= 100.0;   // the shear case's mass factor
  NpfemSettings settings;
  settings.viscous_proxy_refresh_steps = 3;
  std::vector<hs::common::Vec3> f(mesh.vertices_m.size());
  f[0] = {20e-12, 5e-12, 0.0};
  f[5] = {-20e-12, 0.0, 3e-12};
  const double h = 10.7e-6;
  NpfemSolver a(mesh, material, settings, h);
  a.set_external_forces_N(f);
  for (int s = 0; s < 7; ++s) (void)a.step();
  NpfemSolver b(mesh, material, settings, h);
  b.restore_state(a.state());
  for (int s = 0; s < 10; ++s) {
    const auto ra = a.step();
    const auto rb = b.step();
    EXPECT_EQ(ra.iterations, rb.iterations);
    EXPECT_TRUE(ra.converged) << ra.stop_reason;
  }
  const auto xa = a.positions_m(), xb = b.positions_m();
  for (std::size_t i = 0; i < xa.size(); ++i) {
    EXPECT_EQ(xa[i].x, xb[i].x);
    EXPECT_EQ(xa[i].y, xb[i].y);
    EXPECT_EQ(xa[i].z, xb[i].z);
  }
  EXPECT_EQ(a.statistics().viscous_dissipation_J > 0.0, true);
}
