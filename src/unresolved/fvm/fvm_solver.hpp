// SPDX-License-Identifier: MIT
// Volume-averaged incompressible Navier-Stokes (CFDEM "model A") on an FvmGrid, advanced by PISO.
#pragma once

#include <mpi.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/io/checkpoint.hpp"
#include "common/vec3.hpp"
#include <string_view>

#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/block_halo.hpp"
#include "unresolved/fvm/fvm_grid.hpp"
#include "common/fluid_properties.hpp"
#include "unresolved/fvm/momentum_solver.hpp"
#include "unresolved/fvm/pressure_solver.hpp"

namespace hs::unresolved {

/// Loops over fewer unknowns than this run on one thread: an OpenMP fork costs more than the work.
inline constexpr long kParallelRows = 20000;

using FluidProperties = common::FluidProperties;

/// How pressure and velocity are coupled each step, after the implicit momentum predictor:
///  piso:       `correctors` PISO correctors with the full momentum diagonal A (time, exchange, viscous). A mode grows
///              from round-off when the viscous number nu dt / dx^2 is large (measured: 20-cell tube, 2 correctors,
///              steady at 24, blown up at 60; a 3x viscous core blew up at 18): the smooth pressure modes are
///              amplified by about A / M(k) - 1 with M(k) the momentum operator's eigenvalue, which exceeds 1 when
///              the viscous part dominates A.
///  projection: one incremental projection (van Kan 1986) u = u* - (eps / A0) grad(p - p^n) with A0 = eps / dt +
///              Ksl / rho, the part of A without the viscous links: the pressure factor 1 - A0 / M(k) lies in [0, 1)
///              for every mode, so it is stable at any viscous number. First order in time, as the implicit Euler.
///              But short pressure waves relax only by nu dt L / (1 + nu dt L) per step (L the Laplacian's
///              eigenvalue), i.e. slowly at large viscous numbers: right for single-phase flow that settles, wrong
///              around moving DEM spheres (tube-pries, D = 30 um: Ht_d -22.5% against PISO's +2.4%). The rotational
///              form (Timmermans et al. 1996, p += -nu div u*; tried, not kept), exact where the operators commute,
///              jittered by +-5% from step to step with the spheres. Opt-in for single-phase cases; PISO stays the
///              default.
enum class PressureCoupling { piso, projection };

/// "piso" or "projection" (case files' [numerics] pressure_coupling); ConfigError otherwise.
PressureCoupling pressure_coupling_from_name(std::string_view name);

struct PisoSettings {
  double dt_s;                          // fixed CFD time step (CFDEM forbids a variable one)
  int correctors = 2;                   // PISO pressure correctors (icoFoam default 2); projection: one, always
  PressureCoupling coupling = PressureCoupling::piso;
  bool momentum_predictor = true;
  double max_courant = 1.0;             // step() throws NumericalError above it
  SolveTolerance pressure{};            // p: tolerance 1e-6, relTol 0.05 (final corrector: relTol 0)
  double momentum_tolerance = 1e-6;     // BiCGSTAB relative residual ||b - A u|| / ||b|| of the momentum predictor
  int momentum_max_iterations = 1000;
};

/// How a periodic axis is driven: a fixed mean pressure gradient, or a flow rate held by adjusting the
/// gradient every step (as OpenFOAM's meanVelocityForce).
struct FlowDrive {
  enum class Mode { none, pressure_gradient, flow_rate } mode = Mode::none;
  int axis = 2;
  double pressure_gradient_Pa_m = 0.0;  // dp/dx along axis (negative drives flow towards +axis)
  double flow_rate_m3_s = 0.0;
};

struct StepStats {
  int pressure_iterations = 0;          // summed over the correctors of the last step
  int momentum_iterations = 0;          // summed over the three components
  double courant = 0.0;                 // max |u_c| dt / dx after the step
};

/// Model A (Zhou et al. 2010 set II, CFDEM cfdemSolverPiso), per unit mass, interstitial velocity u:
///   eps (du/dt + u.grad u) - div(eps nu grad u) = -eps grad p - (Ksl/rho)(u - Us) + f/rho,
///   d(eps)/dt + div(eps u) = 0,
/// with eps the void fraction, Ksl the implicit exchange coefficient, Us the cell-averaged particle
/// velocity and f the explicit force density, all cell-centred fields set by the coupling. Implicit Euler,
/// central convection linearised with the old fluxes (icoFoam's numerics), PISO with the pressure
/// Laplacian coefficient eps^2 / A (model A). The dev2 transpose stress term vanishes for uniform eps and
/// is not included yet.
/// On a grid over z-slabs (FvmGrid's `slabs`) every rank of `comm` steps its own block: rows numbered globally,
/// ghost planes through the halo, sums over the ranks (docs/cfd-dem.md "Distributed CFD-DEM", step 2).
class FvmSolver {
 public:
  FvmSolver(const FvmGrid& grid, const FluidProperties& fluid, const PisoSettings& piso, const FlowDrive& drive,
            MPI_Comm comm = MPI_COMM_WORLD);

  /// One PISO time step. Throws NumericalError when the Courant number exceeds max_courant or a value
  /// is not finite.
  void step();
  [[nodiscard]] double time_s() const { return time_s_; }
  [[nodiscard]] long steps() const { return steps_; }
  [[nodiscard]] const StepStats& last_stats() const { return stats_; }
  /// The pressure equation's solver (its AMG set-up and reuse counts).
  [[nodiscard]] const PressureSolver& pressure_solver() const { return pressure_; }
  [[nodiscard]] const FvmGrid& grid() const { return grid_; }
  [[nodiscard]] const PisoSettings& settings() const { return piso_; }
  [[nodiscard]] const FluidProperties& fluid() const { return fluid_; }
  [[nodiscard]] const FlowDrive& drive() const { return drive_; }

  // ---- Fields the coupling fills (cell-centred, index (i, j, k) of FvmGrid cells). Call
  // coupling_fields_changed() after writing eps or Ksl, so the pressure matrix is rebuilt. ----
  [[nodiscard]] BlockField<double>& void_fraction() { return eps_; }
  [[nodiscard]] BlockField<double>& implicit_coefficient_kg_m3_s() { return ksl_; }
  [[nodiscard]] BlockField<hs::common::Vec3>& particle_velocity_m_s() { return us_; }
  [[nodiscard]] BlockField<hs::common::Vec3>& explicit_force_density_N_m3() { return force_; }
  /// d(eps)/dt, 1/s, the volume source of the pressure equation (CFDEM step 7).
  [[nodiscard]] BlockField<double>& void_fraction_rate_1_s() { return deps_dt_; }
  /// Local viscosity over the plasma's (>= 1; the suspension's particle stress, coupling/suspension_viscosity):
  /// the viscous link between two velocity nodes takes the mean over the cells it crosses. Asking for it writable
  /// switches the variable-viscosity stencil on (untouched, the stencil is the constant-viscosity one).
  /// Writing it marks the coefficients for rebuilding, as coupling_fields_changed() does. The viscous term is
  /// div(mu grad u): the transpose part div(mu grad u^T) = grad(mu) . grad u, which vanishes for a parallel
  /// flow along a tube, is left out (as for eps).
  [[nodiscard]] BlockField<double>& viscosity_factor() {
    variable_viscosity_ = true;
    coefficients_dirty_ = true;
    return visc_;
  }
  [[nodiscard]] const BlockField<double>& viscosity_factor() const { return visc_; }
  void coupling_fields_changed() { coefficients_dirty_ = true; }
  [[nodiscard]] const BlockField<double>& void_fraction() const { return eps_; }
  [[nodiscard]] const BlockField<hs::common::Vec3>& particle_velocity_m_s() const { return us_; }

  // ---- Results in SI. ----
  /// Fluid velocity at a point (trilinear on each staggered component; wall nodes hold the wall value).
  [[nodiscard]] hs::common::Vec3 velocity_at(const hs::common::Vec3& x_m) const;
  /// grad u at a point: g[a][b] = d u_a / d x_b, 1/s (central differences of velocity_at over one cell).
  [[nodiscard]] std::array<hs::common::Vec3, 3> velocity_gradient_at(const hs::common::Vec3& x_m) const;
  /// div(tau) = div(mu grad u) at a point, N/m^3: the fluid's own viscous stencil at the velocity nodes (its
  /// Shortley-Weller weights, link viscosities and wall values; update_viscous_force), interpolated as the velocity
  /// is. The viscous force density the coupling turns into V_p div(tau) on a particle (model A); where the viscosity
  /// jumps (a cell-rich core) it keeps the fluid's balance, which mu lap(u) of the interpolant does not.
  [[nodiscard]] hs::common::Vec3 viscous_force_density_at(const hs::common::Vec3& x_m) const;
  /// grad p at a point, Pa/m, including the driving mean gradient.
  [[nodiscard]] hs::common::Vec3 pressure_gradient_at(const hs::common::Vec3& x_m) const;
  /// Cell-centred velocity (mean of the two faces of each component), m/s.
  [[nodiscard]] hs::common::Vec3 cell_velocity(int i, int j, int k) const;
  /// Cell pressure, Pa, including the driving mean gradient (zero at the box origin) and the openings' pressure level.
  [[nodiscard]] double cell_pressure_Pa(int i, int j, int k) const;
  /// Mean volume flux through the cross-sections normal to `axis`, m^3/s. Collective (this and the two below: every
  /// rank of the solver's communicator calls them).
  [[nodiscard]] double flow_rate_m3_s(int axis) const;
  /// Volume flux out of the domain through opening k of the grid (grid().openings()[k]), m^3/s: negative at an
  /// inlet. The sum of the face fluxes eps aperture dx^2 u_n over the opening's face nodes (fvm_openings.cpp).
  [[nodiscard]] double opening_flow_rate_m3_s(std::size_t k) const;
  /// The current driving mean pressure gradient along the drive axis, Pa/m.
  [[nodiscard]] double drive_pressure_gradient_Pa_m() const { return fluid_.density_kg_m3 * drive_gradient_; }
  /// Staggered velocity of component c (face nodes), m/s.
  [[nodiscard]] const BlockField<double>& face_velocity(int c) const { return u_[static_cast<std::size_t>(c)]; }
  [[nodiscard]] double courant_number() const;

  // ---- Restart (fvm_checkpoint.cpp). ----
  /// Puts everything the next step() reads into `cp` under names starting with `prefix`: velocities, pressure,
  /// fluxes, the coupling fields, the drive gradient, time and step count.
  void write_state(hs::common::Checkpoint& cp, const std::string& prefix) const;
  /// Restores write_state(); the next step() continues the saved run bit for bit (the matrices are rebuilt from
  /// the restored fields, as they are after every coupling refresh). ConfigError for another grid.
  void read_state(const hs::common::Checkpoint& cp, const std::string& prefix);

 private:
  struct Component {
    std::vector<long> node;                    // padded index of each unknown
    BlockField<int> row;                       // global row of each node (ghost planes: the neighbours'), -1 if not active
    std::vector<int> link_id;                  // per unknown: index into links, -1 when all six are active
    std::vector<std::array<NodeLink, 6>> links;
    std::unique_ptr<MomentumSolver> solver;    // the momentum rows (pattern fixed at construction) and their solve
    std::vector<std::array<int, 7>> slot;      // places in solver->entries(): diagonal, then 6 directions
    Eigen::VectorXd x, b, a, hbya;             // unknowns, source without grad p, diagonal the pressure uses, H/A
  };

  void build_component(int c);
  void build_pressure_rows();
  void build_opening_boundaries();
  void add_outlet_pressures();
  void build_pressure_matrix();
  void spread_momentum_diagonal();
  void assemble_momentum(int c, bool convection = true);
  void compute_drive_response();
  void solve_momentum(int c);
  /// Solves comp_[c].m x = rhs from the guess in x (momentum_solver.hpp).
  MomentumSolve solve_momentum_system(int c, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double tolerance,
                                      int max_iterations);
  void pressure_corrector(bool final);
  void correct_flow_rate();
  void update_fluxes();
  void update_viscous_force();
  void scatter(int c, const Eigen::VectorXd& values, BlockField<double>& field) const;
  void fill_velocity_ghosts(int c, BlockField<double>& field) const;
  void fill_velocity_boundary(int c, int a, BlockField<double>& field) const;
  /// The ghost planes along axis a that another block or the periodic wrap provides: exchange_halo along the
  /// split axis (z over slabs; at one rank it wraps a periodic z through MPI, bit for bit fill_periodic), the
  /// periodic wrap along an unsplit periodic axis. Called after the boundary conditions, so between two blocks the
  /// neighbour's planes replace what a boundary condition wrote there.
  template <typename T>
  void fill_shared_ghosts(BlockField<T>& field, int a) const {
    if (grid_.slabs() != nullptr && a == 2) {
      exchange_halo(field, *grid_.slabs(), a);
    } else if (grid_.periodic(a)) {
      field.fill_periodic(a, grid_.cells()[static_cast<std::size_t>(a)]);
    }
  }
  /// The rows of the lower ranks: this rank's first global row (collective).
  [[nodiscard]] int rows_before(int rows) const;
  /// Over the ranks: the sum, or the largest value (collective).
  [[nodiscard]] double sum_over_ranks(double local) const;
  [[nodiscard]] double max_over_ranks(double local) const;
  /// Velocity nodes of component c along axis a in the whole grid (node_count summed over the blocks along z).
  [[nodiscard]] long global_node_count(int c, int a) const;
  void fill_cell_ghosts(BlockField<double>& field) const;
  void fill_pressure_ghosts();
  [[nodiscard]] double face_average(const BlockField<double>& cell_field, int c, long idx) const;
  [[nodiscard]] double momentum_cv_flux(int c, long idx, int dir) const;
  [[nodiscard]] double link_viscosity(int c, long idx, int dir) const;
  /// A wrapped point in cells from the block origin, (x - origin) / dx per axis.
  [[nodiscard]] std::array<double, 3> in_cells(const hs::common::Vec3& wrapped_m) const;
  [[nodiscard]] hs::common::Vec3 interpolate_components(const std::array<BlockField<double>, 3>& fields,
                                                        const hs::common::Vec3& x_m) const;
  void check_state() const;

  const FvmGrid& grid_;
  MPI_Comm comm_;
  FluidProperties fluid_;
  PisoSettings piso_;
  FlowDrive drive_;
  double h_;
  double drive_gradient_ = 0.0;              // kinematic mean pressure gradient along drive_.axis, m/s^2
  Eigen::VectorXd drive_response_;           // velocity change of one step per unit change of drive_gradient_
  double drive_response_flux_ = 0.0;         // its flow rate, m^3/s per m/s^2
  double time_s_ = 0.0;
  long steps_ = 0;
  bool coefficients_dirty_ = true;
  bool variable_viscosity_ = false;
  StepStats stats_;

  std::array<Component, 3> comp_;
  std::array<BlockField<double>, 3> u_;      // face velocities, m/s
  std::array<BlockField<double>, 3> viscous_force_;   // div(tau) at the velocity nodes, N/m^3 (update_viscous_force)
  std::array<BlockField<double>, 3> hb_;     // H/A on faces (PISO work field)
  std::array<BlockField<double>, 3> phi_;    // face volume fluxes eps * aperture * dx^2 * u, m^3/s
  BlockField<double> p_;                     // kinematic pressure (periodic part), m^2/s^2
  BlockField<int> p_row_;
  std::vector<long> p_cell_;
  int p_first_row_ = 0;                      // this rank's first pressure row (p_row_ holds global rows)
  int p_ref_row_ = -1;                       // pinned cell (global row) when no outlet fixes the pressure level
  std::array<BlockField<double>, 3> a_face_; // momentum diagonal A on the velocity nodes (spread_momentum_diagonal)
  CsrMatrix p_matrix_;                       // the pressure matrix of the last build (its buffers reused)
  std::vector<double> p_rhs_, p_x_;
  PressureSolver pressure_;

  // Pressure outlets of the grid's openings (fvm_openings.cpp): each active face node, the cells on both sides of
  // it, and the kinematic pressure on the face (less p_level_kin_); the source 2 d p_b they add to their cell's row.
  struct OutletFace {
    int axis;
    long node, interior, ghost;
    double p_kin;
  };
  std::vector<OutletFace> outlet_faces_;
  std::vector<double> p_bc_;
  // The pressure outlets' mean (kinematic): p_ holds the pressure less it, and p_kin above is relative to it, so the
  // pressure solve's relative tolerance measures the flow's pressure differences, not the gauge (measured: a 40 Pa
  // outlet in the open tube with the projection lost 2e-3 of the flow rate between sections when solved absolute).
  double p_level_kin_ = 0.0;
  // Per component: ghost nodes beyond a wall side that lie in a pressure outlet's disc (zero gradient there, where
  // the rest of the side reflects about the wall velocity): {axis, high, ghost index, interior index}.
  struct OpenGhost {
    int axis, high;
    std::size_t ghost, interior;
  };
  std::array<std::vector<OpenGhost>, 3> open_ghosts_;

  BlockField<double> eps_, ksl_, deps_dt_, visc_;
  BlockField<hs::common::Vec3> us_, force_;
};

}  // namespace hs::unresolved
