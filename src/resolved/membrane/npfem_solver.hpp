// SPDX-License-Identifier: MIT
// The nodal projective FEM (npFEM) membrane solver of Kotsalos, Latt & Chopard (JCP 398:108905, 2019).
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/SparseCholesky>

#include "common/vec3.hpp"
#include "resolved/membrane/membrane_energy.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "resolved/membrane/membrane_viscosity.hpp"
#include "resolved/membrane/viscous_step_proxy.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {

/// How the centre of mass is held (for drag and lift runs of the coupling, reference §5.2).
enum class CenterConstraint { free, fixed, axis };

/// What one step did: iterations of the minimisation, the final residual and why it stopped.
struct NpfemStepReport {
  int iterations = 0;
  double gradient_max_N = 0.0;   // max over vertices of |grad g| at the end (SI)
  bool converged = false;
  int stagnations = 0;           // line searches that hit the halving limit
  std::string stop_reason;       // "gradient", "objective", "max_iterations", "line_search"
};

/// Running totals for logs and benchmarks.
struct NpfemStatistics {
  long steps = 0;
  long iterations = 0;
  long unconverged_steps = 0;
  long line_search_stops = 0;        // unconverged: no step decreased g where the direction promised more than round-off
  long iteration_cap_stops = 0;      // unconverged because max_iterations was reached
  double unconverged_gradient_sum = 0.0;   // sum over unconverged steps of max |grad g| / tolerance (mean: diagnostics)
  double factorisation_s = 0.0;  // wall time of the one-time sparse Cholesky factorisations
  // The membrane's energy books, joules, summed over the steps (docs/resolved-coupling.md, "Power balance"). Each step
  // of the implicit Euler minimisation satisfies exactly (M the lumped mass, u = x_{n+1} - x_n = h v_{n+1}):
  //   h f.v = dKE + M|v_{n+1} - v_n|^2 / 2 + grad E(x_{n+1}).u + h beta v.Lv + 2 R(u) / h - grad g(x_{n+1}).u,
  // so external_work = dKE + elastic_work + viscous + damping + kinetic_step_loss + solver_residual_work to round-off,
  // and elastic_work - dE is the step's elastic loss. Closed for a free membrane without the friction (the velocity
  // relaxation and the centre constraint change v after the minimisation and are not booked).
  double viscous_dissipation_J = 0.0;   // energy the membrane viscosity dissipated, sum of 2 R(x - x_n) / h over steps
  double external_work_J = 0.0;         // sum h f.v_{n+1}: the work of the external (fluid) force
  double elastic_work_J = 0.0;          // sum grad E(x_{n+1}).(x_{n+1} - x_n): stored elastic energy + the step's loss
  double damping_dissipation_J = 0.0;   // sum h beta v.Lv: the Rayleigh damping's dissipation
  double kinetic_step_loss_J = 0.0;     // sum M|v_{n+1} - v_n|^2 / 2: implicit Euler's loss of kinetic energy
  double solver_residual_work_J = 0.0;  // sum -grad g(x_{n+1}).u: the work of what the minimisation left unbalanced
};

/// One membrane. Implicit Euler as the minimisation g(x) = |x - y|^2_{M~}/(2 h^2) + E(x) (reference §3.1), with
/// M~ = M + h beta L (stiffness-proportional Rayleigh damping), solved by L-BFGS (Liu et al. 2017) preconditioned by
/// the constant proxy H0 = M~/h^2 + L (+ a rank-2 Woodbury term for the global volume and area energies), factorised
/// once; or by the plain projective-dynamics local/global iteration x <- x - H0^-1 grad g (which, for the PD terms,
/// is exactly Bouaziz et al. 2014's global solve after the local projections). After convergence the velocity is
/// relaxed towards the rigid-body motion by C_alpha = zeta h / (zeta h + m), the implicit step of the vertex friction
/// zeta = zeta_A A / n (MembraneParameters::deformation_friction_Pa_s_m; viscoelasticity, reference §3.3 step 6).
/// A membrane viscosity (MembraneParameters::viscosity_N_s_m) adds the step's dissipation potential h R((x - x_n) / h)
/// to g, with the triangles' geometry frozen at x_n (MembraneViscosity): quadratic in x, so the step stays a
/// minimisation and the viscous stress is implicit (backward Euler); the proxy then also holds the viscous Hessian at
/// x_n and is refactorised every step (ViscousStepProxy).
/// Speed (the minimiser is unchanged): a step starts from the better of x_n and y + c, with c the corrections x* - y
/// of the two previous steps linearly extrapolated (until two steps are done: the better of x_n and y); the L-BFGS
/// pairs are kept from step to step (the Hessian of g changes little between steps); both are in state(), so a
/// resumed run is bit for bit the uninterrupted one.
/// Interface in SI; internally um, us, fg (force pN), as Palabos-npFEM.
class NpfemSolver {
 public:
  NpfemSolver(const TriangleMesh& rest_mesh, const MembraneParameters& material, const NpfemSettings& settings,
              double time_step_s);
  ~NpfemSolver();
  NpfemSolver(const NpfemSolver&) = delete;
  NpfemSolver& operator=(const NpfemSolver&) = delete;

  /// External force per vertex in newtons, held until changed (the coupling sets it before every step).
  /// A non-finite force throws NumericalError naming the vertex.
  void set_external_forces_N(std::span<const hs::common::Vec3> forces_N);
  void clear_external_forces();
  /// One implicit step of length time_step_s. Throws NumericalError if the solve diverges (non-finite values,
  /// or an edge stretched beyond 20x its rest length); the state is then left at the previous step.
  NpfemStepReport step();

  /// Holds the centre of mass where it is now (fixed), or lets it move only along `axis` (axis).
  void set_center_constraint(CenterConstraint constraint, hs::common::Vec3 axis = {1.0, 0.0, 0.0});
  /// Minimise the step exactly along the rigid translations (a uniform shift of the minimiser, free: g is quadratic
  /// there), so that the step conserves momentum to round-off whatever the iteration did: sum m v changes by h sum f.
  /// Off by default (bit-for-bit with earlier runs); the ibm_reaction coupling turns it on (coupled_cell.hpp).
  void set_exact_translation(bool on) { exact_translation_ = on; }
  /// Moves the whole cell rigidly (placing it in a domain).
  void translate_m(const hs::common::Vec3& shift_m);

  /// Checkpoint state (flat): positions, velocities and external forces of every vertex, the centre target, then the
  /// solver's memory (start predictor, L-BFGS pairs; with viscosity the step proxy's age and geometry) so that a
  /// resumed run repeats the uninterrupted one bit for bit.
  [[nodiscard]] std::vector<double> state() const;
  /// Restores state() of a solver built from the same mesh and settings (a state without the solver memory is
  /// accepted and starts it empty); throws std::invalid_argument on a size mismatch.
  void restore_state(std::span<const double> state);

  [[nodiscard]] int vertex_count() const { return static_cast<int>(x_um_.rows()); }
  [[nodiscard]] const std::vector<std::array<int, 3>>& triangles() const { return energy_->triangles(); }
  [[nodiscard]] std::vector<hs::common::Vec3> positions_m() const;
  [[nodiscard]] std::vector<hs::common::Vec3> velocities_m_s() const;
  [[nodiscard]] TriangleMesh current_mesh() const;
  [[nodiscard]] std::vector<hs::common::Vec3> vertex_normals() const;
  [[nodiscard]] std::vector<double> vertex_areas_m2() const;
  [[nodiscard]] hs::common::Vec3 centroid_m() const;
  [[nodiscard]] double area_m2() const;
  [[nodiscard]] double volume_m3() const;
  [[nodiscard]] double rest_area_m2() const;
  [[nodiscard]] double rest_volume_m3() const;
  [[nodiscard]] double vertex_mass_kg() const;
  /// The membrane's elastic energy E(x) at the current positions, joules (power balances; one energy evaluation).
  [[nodiscard]] double elastic_energy_J() const;
  /// The kinetic energy sum m |v|^2 / 2 of the lumped vertex masses, joules.
  [[nodiscard]] double kinetic_energy_J() const;
  [[nodiscard]] double time_step_s() const { return h_us_ * 1e-6; }
  /// The per-step relaxation C_alpha this step and vertex mass give the deformation friction (0 = elastic).
  [[nodiscard]] double velocity_relaxation() const { return velocity_relaxation_; }
  [[nodiscard]] const NpfemStatistics& statistics() const { return stats_; }
  /// The statistics as a flat vector for checkpoints (all but the wall time of the factorisations), and back; a
  /// resumed run then reports the whole run's counts and energy books. A shorter vector (an older layout) is refused.
  [[nodiscard]] std::vector<double> statistics_state() const;
  void restore_statistics(std::span<const double> state);

 private:
  struct LineSearchResult {
    double objective;
    bool accepted;
  };
  struct Workspace;   // preallocated buffers, the blocked proxy back-solve, the L-BFGS memory, the start predictor
  double objective(const Positions& x, const Positions& y, Positions& gradient);
  /// Backtracking alpha = 1, 1/2, ... until the Armijo and curvature (Wolfe) conditions hold; xt, gt: last trial.
  LineSearchResult line_search(const Positions& x, const Positions& d, const Positions& y, double fx, double gd,
                               Positions& xt, Positions& gt);
  void apply_inverse_proxy(const Positions& g, Positions& out) const;
  /// (Re)computes the Woodbury vectors H^-1 u and the core inverse (after the proxy changed).
  void update_woodbury();
  /// With viscosity: refactorises the step proxy at x and updates the Woodbury terms.
  void refresh_step_proxy(const Positions& x);
  /// The start of the minimisation (see the class comment); returns g(x) and writes its gradient into g.
  void restore_memory(std::span<const double> memory);
  double start(const Positions& xn, const Positions& y, Positions& x, Positions& g);
  /// Both start from x with gradient g and objective fx (already evaluated) and leave the minimiser in x.
  NpfemStepReport minimise(Positions& x, const Positions& y, Positions& g, double fx);
  NpfemStepReport projective_dynamics(Positions& x, const Positions& y, Positions& g, double fx);
  /// Books the step from x_n to x (v = (x - x_n) / h) into stats_ (NpfemStatistics); grad_e = grad E(x).
  /// rayleigh = R(x - x_n), whose gradient is in the workspace (gv).
  void book_energy(const Positions& xn, const Positions& x, const Positions& y, const Positions& grad_e,
                   double rayleigh);
  void relax_velocity(Positions& v, const Positions& x) const;
  void apply_center_constraint();
  void check_state(const Positions& x, const Positions& v) const;
  [[nodiscard]] double max_row_norm(const Positions& g) const;

  std::unique_ptr<MembraneEnergy> energy_;
  std::unique_ptr<MembraneViscosity> viscosity_;   // null without membrane viscosity
  std::unique_ptr<ViscousStepProxy> step_proxy_;   // with viscosity: H0 + the viscous Hessian at a recent x_n
  int step_proxy_age_ = 0;                         // steps since its refactorisation (checkpointed)
  NpfemSettings settings_;
  MembraneParameters material_;
  double h_us_;
  double mass_fg_;
  double velocity_relaxation_;                  // C_alpha per step, from the deformation friction
  double force_scale_pN_;                       // G_s * mean rest edge: the elastic force of one vertex
  double max_edge_um_;                          // 20 x the longest rest edge: beyond it the solve has diverged
  Eigen::SparseMatrix<double> damped_mass_;     // M~ = M + h beta L  (fg)
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> proxy_;        // H0 = M~/h^2 + L
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> damped_mass_solver_;
  Positions woodbury_u_[2];                     // rest gradients of V and A (rank-2 global proxy)
  Positions woodbury_z_[2];                     // H0^-1 u
  double woodbury_coef_[2] = {0.0, 0.0};        // k_V / V0, k_A / A0
  double woodbury_core_diag_[2] = {0.0, 0.0};   // 1 / coef of the active terms
  Eigen::Matrix2d woodbury_core_inv_;
  int woodbury_rank_ = 0;
  Positions x_um_;
  Positions v_um_us_;
  Positions f_ext_pN_;
  CenterConstraint center_constraint_ = CenterConstraint::free;
  bool exact_translation_ = false;
  Eigen::Vector3d center_target_um_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d center_axis_ = Eigen::Vector3d::UnitX();
  NpfemStatistics stats_;
  std::unique_ptr<Workspace> work_;
};

}  // namespace hs::resolved
