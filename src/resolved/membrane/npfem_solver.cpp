// SPDX-License-Identifier: MIT
// npFEM solver: set-up (units, masses, the once-factorised proxy), the time step and the SI interface.
#include "resolved/membrane/npfem_solver.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <fmt/format.h>

#include "common/errors.hpp"
#include "resolved/membrane/npfem_workspace.hpp"

namespace hs::resolved {
namespace {

using hs::common::Vec3;

// Internal units (Palabos-npFEM, reference §1.3): length um, time us, mass fg => force pN, energy pN um.
constexpr double um_per_m = 1e6;
constexpr double us_per_s = 1e6;
constexpr double pN_per_N = 1e12;
constexpr double pN_um_per_J = 1e18;
constexpr double pN_um_per_N_m = 1e6;   // N/m -> pN/um
constexpr double pN_us_per_um_per_N_s_m = 1e12;   // N s/m -> pN us/um

Positions to_positions(const std::vector<Vec3>& v, double scale) {
  Positions p(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t i = 0; i < v.size(); ++i) p.row(static_cast<Eigen::Index>(i)) << v[i].x * scale, v[i].y * scale, v[i].z * scale;
  return p;
}

std::vector<Vec3> to_vec3(const Positions& p, double scale) {
  std::vector<Vec3> v(static_cast<std::size_t>(p.rows()));
  for (Eigen::Index i = 0; i < p.rows(); ++i) v[static_cast<std::size_t>(i)] = Vec3{p(i, 0), p(i, 1), p(i, 2)} * scale;
  return v;
}

EnergyModuli internal_moduli(const MembraneParameters& m) {
  const double lambda = 4.0 * m.shear_modulus_N_m * pN_um_per_N_m;   // small-strain G_s = lambda / 4
  return {.law = m.law,
          .skalak_lambda_pN_um = lambda,
          .hardening_mu_pN_um = m.strain_hardening_ratio * lambda,
          .area_weight_pN_um = 2.0 * m.area_modulus_N_m * pN_um_per_N_m,
          .bending_pN_um = m.bending_modulus_J * pN_um_per_J,
          .volume_modulus_pN_um2 = m.volume_modulus_Pa,   // 1 Pa = 1 pN/um^2
          .global_area_pN_um = m.global_area_modulus_N_m * pN_um_per_N_m};
}

double dot(const Positions& a, const Positions& b) { return (a.array() * b.array()).sum(); }

}  // namespace

NpfemSolver::NpfemSolver(const TriangleMesh& rest_mesh, const MembraneParameters& material,
                         const NpfemSettings& settings, double time_step_s)
    : settings_(settings), material_(material), h_us_(time_step_s * us_per_s) {
  if (!(time_step_s > 0.0)) throw hs::common::ConfigError(fmt::format("npFEM time_step_s = {} must be > 0", time_step_s));
  x_um_ = to_positions(rest_mesh.vertices_m, um_per_m);
  const Eigen::RowVector3d c = x_um_.colwise().mean();
  const Positions rest_um = x_um_.rowwise() - c;
  energy_ = rest_mesh.stress_free_vertices_m.empty()
                ? std::make_unique<MembraneEnergy>(rest_um, rest_mesh.triangles, internal_moduli(material))
                : std::make_unique<MembraneEnergy>(rest_um, to_positions(rest_mesh.stress_free_vertices_m, um_per_m),
                                                   rest_mesh.triangles, internal_moduli(material));
  const int n = vertex_count();
  v_um_us_.setZero(n, 3);
  f_ext_pN_.setZero(n, 3);
  mass_fg_ = material.density_kg_m3 * energy_->rest_volume() / n;   // 1 kg/m^3 = 1 fg/um^3
  // Friction of a vertex times the step over its mass (SI): the backward-Euler step of m dv/dt = -zeta v is
  // v <- v / (1 + zeta h / m), i.e. v += C (0 - v) with C = zeta h / (zeta h + m).
  const double zeta_h_over_m = material.deformation_friction_Pa_s_m * energy_->rest_area() * 1e-12 / n *
                               time_step_s / (mass_fg_ * 1e-18);
  velocity_relaxation_ = zeta_h_over_m / (1.0 + zeta_h_over_m);
  double edge_sum = 0.0;
  double edge_max = 0.0;
  const auto edges = mesh_edges(rest_mesh);
  for (const auto& e : edges) {
    const double len = (x_um_.row(e[0]) - x_um_.row(e[1])).norm();
    edge_sum += len;
    edge_max = std::max(edge_max, len);
  }
  force_scale_pN_ = material.shear_modulus_N_m * pN_um_per_N_m * edge_sum / static_cast<double>(edges.size());
  max_edge_um_ = 20.0 * edge_max;

  const auto start = std::chrono::steady_clock::now();
  const Eigen::SparseMatrix<double> l = energy_->stiffness_proxy();   // full weights: Rayleigh damping
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  damped_mass_ = mass_fg_ * identity + (h_us_ * material.rayleigh_beta_s * us_per_s) * l;
  damped_mass_solver_.compute(damped_mass_);
  const Eigen::SparseMatrix<double> h0 = damped_mass_ / (h_us_ * h_us_) + energy_->stiffness_proxy(settings.area_proxy_fraction);
  proxy_.compute(h0);
  if (proxy_.info() != Eigen::Success || damped_mass_solver_.info() != Eigen::Success) {
    throw hs::common::NumericalError("npFEM: the Hessian proxy is not positive definite (check the mesh and moduli)");
  }
  work_ = std::make_unique<Workspace>(settings.lbfgs_history, n);
  work_->proxy = BlockedLdlt(proxy_);
  work_->damped_mass = BlockedLdlt(damped_mass_solver_);
  // Rank-2 Woodbury correction for the global volume and area energies, from their rest gradients.
  Positions gv, ga;
  energy_->volume_area_gradients(rest_um, gv, ga);
  const EnergyModuli& k = energy_->moduli();
  woodbury_coef_[0] = k.volume_modulus_pN_um2 / energy_->rest_volume();
  woodbury_coef_[1] = k.global_area_pN_um / energy_->rest_area();
  const Positions* grads[2] = {&gv, &ga};
  for (int j = 0; j < 2; ++j) {
    if (woodbury_coef_[j] <= 0.0) continue;
    woodbury_u_[woodbury_rank_] = *grads[j];
    woodbury_core_diag_[woodbury_rank_] = 1.0 / woodbury_coef_[j];
    ++woodbury_rank_;
  }
  if (material.viscosity_N_s_m > 0.0) {
    viscosity_ = std::make_unique<MembraneViscosity>(rest_mesh.triangles, material.viscosity_N_s_m * pN_us_per_um_per_N_s_m);
    viscosity_->freeze(x_um_);
    step_proxy_ = std::make_unique<ViscousStepProxy>(h0, *viscosity_, h_us_);
    step_proxy_->refresh(rest_um);
    if (!step_proxy_->ok()) throw hs::common::NumericalError("npFEM: the viscous Hessian proxy is not positive definite");
  }
  update_woodbury();
  stats_.factorisation_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

NpfemSolver::~NpfemSolver() = default;

void NpfemSolver::refresh_step_proxy(const Positions& x) {
  step_proxy_->refresh(x);
  if (!step_proxy_->ok()) throw hs::common::NumericalError("npFEM: the viscous Hessian proxy is not positive definite");
  step_proxy_age_ = 0;
  update_woodbury();
}

void NpfemSolver::update_woodbury() {
  Eigen::Matrix2d core = Eigen::Matrix2d::Zero();
  for (int a = 0; a < woodbury_rank_; ++a) {
    if (step_proxy_) {
      step_proxy_->solve(woodbury_u_[a], woodbury_z_[a]);
    } else {
      woodbury_z_[a] = proxy_.solve(woodbury_u_[a]);
    }
    core(a, a) = woodbury_core_diag_[a];
  }
  for (int a = 0; a < woodbury_rank_; ++a)
    for (int b = 0; b < woodbury_rank_; ++b) core(a, b) += dot(woodbury_u_[a], woodbury_z_[b]);
  woodbury_core_inv_ = Eigen::Matrix2d::Identity();
  if (woodbury_rank_ > 0) woodbury_core_inv_.topLeftCorner(woodbury_rank_, woodbury_rank_) =
      core.topLeftCorner(woodbury_rank_, woodbury_rank_).inverse();
}

void NpfemSolver::apply_inverse_proxy(const Positions& g, Positions& out) const {
  if (step_proxy_) {
    step_proxy_->solve(g, out);
  } else {
    work_->proxy.solve(g, out);
  }
  if (woodbury_rank_ == 0) return;
  Eigen::Vector2d ut = Eigen::Vector2d::Zero();
  for (int a = 0; a < woodbury_rank_; ++a) ut[a] = dot(woodbury_u_[a], out);
  const Eigen::Vector2d coef = woodbury_core_inv_ * ut;
  for (int a = 0; a < woodbury_rank_; ++a) out -= coef[a] * woodbury_z_[a];
}

double NpfemSolver::objective(const Positions& x, const Positions& y, Positions& gradient) {
  const double e = energy_->evaluate(x, gradient);
  Positions& d = work_->d;
  Positions& md = work_->md;
  d.noalias() = x - y;
  md.noalias() = damped_mass_ * d;
  const double inv_h2 = 1.0 / (h_us_ * h_us_);
  gradient += inv_h2 * md;
  if (!viscosity_) return e + 0.5 * inv_h2 * dot(d, md);
  Workspace& w = *work_;
  w.u.noalias() = x - w.xn;
  w.gv.setZero();
  const double r = viscosity_->rayleigh(w.u, w.gv);
  gradient += w.gv / h_us_;
  return e + 0.5 * inv_h2 * dot(d, md) + r / h_us_;
}

double NpfemSolver::max_row_norm(const Positions& g) const { return g.rowwise().norm().maxCoeff(); }

void NpfemSolver::set_external_forces_N(std::span<const Vec3> forces_N) {
  if (static_cast<int>(forces_N.size()) != vertex_count()) {
    throw std::invalid_argument(fmt::format("npFEM: {} external forces given for {} vertices", forces_N.size(), vertex_count()));
  }
  for (int i = 0; i < vertex_count(); ++i) {
    if (!std::isfinite(forces_N[i].x) || !std::isfinite(forces_N[i].y) || !std::isfinite(forces_N[i].z)) {
      throw hs::common::NumericalError(fmt::format("npFEM: the external force on vertex {} is not finite ({}, {}, {}) N",
                                                   i, forces_N[i].x, forces_N[i].y, forces_N[i].z));
    }
    f_ext_pN_.row(i) << forces_N[i].x * pN_per_N, forces_N[i].y * pN_per_N, forces_N[i].z * pN_per_N;
  }
}

void NpfemSolver::clear_external_forces() { f_ext_pN_.setZero(); }

NpfemStepReport NpfemSolver::step() {
  const Eigen::RowVector3d c = x_um_.colwise().mean();   // work about the centroid (conditioning)
  const Positions xn = x_um_.rowwise() - c;
  Workspace& w = *work_;
  w.rhs.noalias() = mass_fg_ * v_um_us_ + h_us_ * f_ext_pN_;
  w.damped_mass.solve(w.rhs, w.dir);
  const Positions y = xn + h_us_ * w.dir;
  if (viscosity_) {
    viscosity_->freeze(xn);
    w.xn = xn;
    if (step_proxy_age_ >= settings_.viscous_proxy_refresh_steps) refresh_step_proxy(xn);
    ++step_proxy_age_;
  }
  Positions x, g;
  const double fx = start(xn, y, x, g);
  const NpfemStepReport report =
      settings_.iteration == NpfemIteration::lbfgs ? minimise(x, y, g, fx) : projective_dynamics(x, y, g, fx);
  // grad E(x) from the minimiser's gradient: g = grad E + M~ (x - y) / h^2 + grad R(x - x_n) / h (energy books).
  const double inv_h2 = 1.0 / (h_us_ * h_us_);
  Positions grad_e = g - inv_h2 * (damped_mass_ * (x - y));
  double rayleigh = 0.0;
  w.gv.setZero();
  if (viscosity_) {
    w.u.noalias() = x - xn;
    rayleigh = viscosity_->rayleigh(w.u, w.gv);   // R and grad R do not see a uniform shift (below)
    grad_e -= w.gv / h_us_;
  }
  // g is quadratic along the three rigid translations (E and the damping Laplacian do not see them, 1^T M~ = m 1^T)
  // with its minimum at mean(x) = mean(y); a minimisation that starts from x_n and stops early (cap, short line
  // search) leaves part of that. Removing it makes sum_i m v_i change by exactly h sum_i f_i.
  if (exact_translation_) x.rowwise() += y.colwise().mean() - x.colwise().mean();
  w.correction[1].swap(w.correction[0]);
  w.correction[0].noalias() = x - y;
  w.corrections = std::min(w.corrections + 1, 2);
  book_energy(xn, x, y, grad_e, rayleigh);
  Positions v = (x - xn) / h_us_;
  relax_velocity(v, x);
  x = xn + h_us_ * v;
  check_state(x, v);
  stats_.external_work_J += h_us_ * dot(f_ext_pN_, v) / pN_um_per_J;   // the displacement the step really made
  x_um_ = x.rowwise() + c;
  v_um_us_ = v;
  apply_center_constraint();
  ++stats_.steps;
  stats_.iterations += report.iterations;
  if (!report.converged) {
    ++stats_.unconverged_steps;
    if (report.stop_reason == "line_search") ++stats_.line_search_stops;
    if (report.stop_reason == "max_iterations") ++stats_.iteration_cap_stops;
    stats_.unconverged_gradient_sum += report.gradient_max_N * pN_per_N / (settings_.gradient_tolerance * force_scale_pN_);
  }
  return report;
}

void NpfemSolver::book_energy(const Positions& xn, const Positions& x, const Positions& y, const Positions& grad_e,
                              double rayleigh) {
  const Workspace& w = *work_;
  const Positions u = x - xn;
  const Positions v = u / h_us_;
  const Positions mv = damped_mass_ * v;   // M v + h beta L v
  const Positions dv = v - v_um_us_;
  // The minimisation's gradient at the final x (after the uniform shift): what is left unbalanced.
  const Positions residual = grad_e + (damped_mass_ * (x - y)) / (h_us_ * h_us_) + w.gv / h_us_;
  stats_.viscous_dissipation_J += 2.0 * rayleigh / h_us_ / pN_um_per_J;
  stats_.elastic_work_J += dot(grad_e, u) / pN_um_per_J;
  stats_.damping_dissipation_J += (dot(v, mv) - mass_fg_ * v.squaredNorm()) / pN_um_per_J;
  stats_.kinetic_step_loss_J += 0.5 * mass_fg_ * dv.squaredNorm() / pN_um_per_J;
  stats_.solver_residual_work_J -= dot(residual, u) / pN_um_per_J;
}

double NpfemSolver::start(const Positions& xn, const Positions& y, Positions& x, Positions& g) {
  const Workspace& w = *work_;
  Positions g_other;
  const double f_xn = objective(xn, y, g);
  const bool predict = w.corrections == 2;
  // The correction x* - y = -h^2 M~^-1 grad E(x*) follows the elastic forces, which change slowly from step to step:
  // extrapolate it linearly. x_n stays a candidate: it is the safe start where that fails (long quasi-static steps).
  if (predict) {
    x.noalias() = y + 2.0 * w.correction[0] - w.correction[1];
  } else {
    x = y;
  }
  const double f_other = objective(x, y, g_other);
  if (f_xn <= f_other) {   // the better start of the two
    x = xn;
    return f_xn;
  }
  g.swap(g_other);
  return f_other;
}

void NpfemSolver::relax_velocity(Positions& v, const Positions& x) const {
  const double c_alpha = velocity_relaxation_;
  if (c_alpha <= 0.0) return;
  const Eigen::RowVector3d xc = x.colwise().mean();
  const Eigen::RowVector3d vc = v.colwise().mean();   // equal lumped masses
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (int i = 0; i < vertex_count(); ++i) {
    const Eigen::Vector3d r = (x.row(i) - xc).transpose();
    inertia += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
    momentum += r.cross(v.row(i).transpose());
  }
  const Eigen::Vector3d omega = inertia.ldlt().solve(momentum);
  for (int i = 0; i < vertex_count(); ++i) {
    const Eigen::Vector3d r = (x.row(i) - xc).transpose();
    const Eigen::RowVector3d rigid = vc + omega.cross(r).transpose();
    v.row(i) += c_alpha * (rigid - v.row(i));
  }
}

void NpfemSolver::check_state(const Positions& x, const Positions& v) const {
  const bool finite = x.allFinite() && v.allFinite();
  double longest = 0.0;
  if (finite) {
    for (const auto& t : triangles()) {
      for (int k = 0; k < 3; ++k) longest = std::max(longest, (x.row(t[k]) - x.row(t[(k + 1) % 3])).norm());
    }
  }
  if (!finite || longest > max_edge_um_) {
    throw hs::common::NumericalError(fmt::format(
        "npFEM: membrane solve diverged at step {} ({}; longest edge {:.3g} um, limit {:.3g} um); the state is kept "
        "at the previous step. Reduce the time step or the external forces, or check the moduli",
        stats_.steps + 1, finite ? "edge blow-up" : "non-finite positions", longest, max_edge_um_));
  }
}

void NpfemSolver::set_center_constraint(CenterConstraint constraint, Vec3 axis) {
  center_constraint_ = constraint;
  center_target_um_ = x_um_.colwise().mean().transpose();
  center_axis_ = Eigen::Vector3d(axis.x, axis.y, axis.z).normalized();
}

void NpfemSolver::apply_center_constraint() {
  if (center_constraint_ == CenterConstraint::free) return;
  Eigen::Vector3d dx = x_um_.colwise().mean().transpose() - center_target_um_;
  Eigen::Vector3d dv = v_um_us_.colwise().mean().transpose();
  if (center_constraint_ == CenterConstraint::axis) {
    dx -= dx.dot(center_axis_) * center_axis_;
    dv -= dv.dot(center_axis_) * center_axis_;
  }
  x_um_.rowwise() -= dx.transpose();
  v_um_us_.rowwise() -= dv.transpose();
}

void NpfemSolver::translate_m(const Vec3& shift_m) {
  x_um_.rowwise() += Eigen::RowVector3d(shift_m.x, shift_m.y, shift_m.z) * um_per_m;
  center_target_um_ += Eigen::Vector3d(shift_m.x, shift_m.y, shift_m.z) * um_per_m;
}

std::vector<Vec3> NpfemSolver::positions_m() const { return to_vec3(x_um_, 1.0 / um_per_m); }
std::vector<Vec3> NpfemSolver::velocities_m_s() const { return to_vec3(v_um_us_, 1.0); }   // 1 um/us = 1 m/s
TriangleMesh NpfemSolver::current_mesh() const { return {positions_m(), triangles()}; }
std::vector<Vec3> NpfemSolver::vertex_normals() const { return hs::resolved::vertex_normals(current_mesh()); }
std::vector<double> NpfemSolver::vertex_areas_m2() const { return hs::resolved::vertex_areas_m2(current_mesh()); }
Vec3 NpfemSolver::centroid_m() const {
  const Eigen::RowVector3d c = x_um_.colwise().mean() / um_per_m;
  return {c[0], c[1], c[2]};
}
double NpfemSolver::area_m2() const { return energy_->area(x_um_) * 1e-12; }
double NpfemSolver::volume_m3() const {
  return energy_->volume(Positions(x_um_.rowwise() - x_um_.colwise().mean())) * 1e-18;
}
double NpfemSolver::rest_area_m2() const { return energy_->rest_area() * 1e-12; }
double NpfemSolver::rest_volume_m3() const { return energy_->rest_volume() * 1e-18; }
double NpfemSolver::vertex_mass_kg() const { return mass_fg_ * 1e-18; }
double NpfemSolver::kinetic_energy_J() const { return 0.5 * mass_fg_ * v_um_us_.squaredNorm() / pN_um_per_J; }
double NpfemSolver::elastic_energy_J() const {
  Positions gradient;
  return energy_->evaluate(Positions(x_um_.rowwise() - x_um_.colwise().mean()), gradient) / pN_um_per_J;
}

}  // namespace hs::resolved
