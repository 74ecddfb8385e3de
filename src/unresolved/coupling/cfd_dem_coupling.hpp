// SPDX-License-Identifier: MIT
// The CFD-DEM coupling of one FvmSolver and one DemSystem (CFDEM model A), with closures chosen by name.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "closures/deformation_closure.hpp"
#include "closures/drag_closure.hpp"
#include "closures/lift_closure.hpp"
#include "closures/wall_correction.hpp"
#include "common/vec3.hpp"
#include "unresolved/coupling/channel_frame.hpp"
#include "unresolved/coupling/diffusion_smoothing.hpp"
#include "unresolved/coupling/divided_void_fraction.hpp"
#include "unresolved/coupling/self_mobility.hpp"
#include "unresolved/coupling/suspension_viscosity.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// How the fluid receives the drag. implicit: Ksl in the fluid matrix (CFDEM implicitCouple, stable at any
/// dt_CFD / tau_p) plus the explicit remainder -J/(V dt) - Ksl (Us - U^n), so that the fluid's total is minus
/// the DEM's exact drag impulse J up to the transient Ksl (U^n - U^{n+1}); that imbalance is measured on the
/// staggered nodes after each step and given back on the next (deferred correction), so fluid + particle
/// momentum minus the pending imbalance is conserved to round-off. explicit_impulse: the fluid gets exactly
/// -J/(V dt) and no Ksl (conservative in the same step, stable only for dt_CFD below rho eps / Ksl).
enum class FluidDrag { implicit, explicit_impulse };

/// Where the closures' "tube" comes from. tube: a straight tube given by axis, axis_point_m and tube_radius_m (the
/// lift along the radius, gamma+ from R, u_r+ along the axis over the case's mean velocity). channel: from the
/// grid's shape and the local flow at every sphere (channel_frame.hpp; docs/cfd-dem.md "Closure inputs without a
/// tube"), for any geometry; in a straight tube it gives the tube frame's values (channel_frame_test).
enum class ClosureFrame { tube, channel };

/// How many DEM steps a CFD step takes. fixed: n_coupling, the inertial step dt_CFD / n_coupling <= 0.1
/// min(t_Rayleigh, t_Hertz) the case checked. drag_limited: as few as the drag-limited step allows
/// (drag_limited_step.hpp: the contacts relax against the fluid drag), at most n_coupling, chosen anew at the
/// start of every CFD step; where the rule does not apply (no fluid torque, a contact not overdamped) n_coupling.
enum class DemSubsteps { fixed, drag_limited };

struct CouplingSettings {
  int n_coupling = 1;                 // DEM steps per CFD step (dt_CFD = n_coupling dt_DEM): the inertial count
  DemSubsteps dem_substeps = DemSubsteps::drag_limited;
  // The fluid torque pi mu d^3 (Omega_f - w) on each sphere (Stokes' rotlet, Omega_f half the vorticity at its
  // centre), integrated exactly (exponential_verlet.hpp); the fluid gets no reaction torque (model A). It makes
  // the rotation overdamped like the translation, which the drag-limited step needs.
  bool fluid_torque = true;
  double eps_min = 0.1;               // CFDEM alphaMin default (unresolved-methods.md sec. 2)
  int refresh_every = 1;              // CFD steps between rebuilds of the eps/Ksl pressure matrix
  FluidDrag fluid_drag = FluidDrag::implicit;
  bool void_fraction_feedback = true; // false: the fluid keeps eps = 1 (dilute limit, conservation tests)
  // false: one-way coupling, the fluid receives neither the drag nor the lift reaction (Ksl = 0, no explicit
  // source): the particles see the undisturbed flow. For verification of the drag law (sphere_in_tube_drag_test)
  // and the dilute limit; two-way is the model.
  bool two_way = true;
  // d(eps)/dt as the pressure equation's volume source. Without smoothing, a marker crossing a cell face
  // changes eps by V_p / (29 V_cell) at once (0.12 for an RBC sphere in a 3 um cell), a source spike that
  // destabilised the tube case (methods note sec. 8 item 5-6); off there until a smoothing model exists.
  bool void_fraction_rate = true;
  bool pressure_force = true;         // F_p = -V_p grad p (model A requires it)
  bool viscous_force = true;          // F_v = V_p div(tau) (model A requires it)
  ClosureFrame closure_frame = ClosureFrame::tube;
  // Tube frame for the closures' groups and the radial lift direction: axis through axis_point_m along axis.
  int axis = 2;
  hs::common::Vec3 axis_point_m{};
  double tube_radius_m = 0.0;         // R_c in gamma+ = gammadot R_c^2 / nu
  // Confinement factor K(d_p / 2 R_c) on every particle's drag (closures/wall_correction.hpp): the closures
  // describe an unbounded sphere; haberman_sayre makes them the on-axis drag in the tube of radius tube_radius_m
  // (channel frame: of the local channel radius R_c).
  hs::closures::WallCorrection wall_correction = hs::closures::WallCorrection::none;
  // true: the closures get the undisturbed velocity estimate u_f - M F instead of the interpolated u_f, with F the
  // force each sphere gave the fluid in the last step (drag and lift) and M the grid's self-mobility measured on
  // this tube (self_mobility.hpp), divided by the suspension viscosity's factor at the sphere. Two-way coupling only;
  // needs tube_radius_m, and spheres no larger than a cell unless the exchange is smoothed.
  bool self_induced_correction = false;
  // The cells' stress as a local viscosity factor of the smoothed volume fraction (suspension_viscosity.hpp),
  // refreshed with eps; needs void_fraction_feedback.
  SuspensionViscosity suspension_viscosity = SuspensionViscosity::none;
  // > 0: the void fraction, the exchanged forces (explicit and implicit) and with them the cells' stress are
  // smoothed over this length, m (diffusion_smoothing.hpp), so the particles' footprint is a physical length and
  // not the grid's cell (issue #25). 0: each field stays on the cells the divided markers fall in.
  double smoothing_length_m = 0.0;
  // Where the generalised buoyancy V_p (-grad p + div tau) is taken. false ("centre"): sampled at the sphere's centre.
  // true ("footprint"): the fluid's force density at the cell centres, smoothed as the solid fraction is, averaged over
  // the sphere's 29 markers' cells: the adjoint of how the sphere's volume reaches eps, so that the spheres together
  // receive exactly sum_c (1 - eps_c) V_c (-grad p + div tau)_c and the mixture's momentum closes (the centre value
  // contains each sphere's own reaction peaked there; docs/cfd-dem.md).
  bool buoyancy_over_footprint = false;
};

/// Closures by role; drag is required, lift and deformation may be null (no lift, DI = 0).
struct CouplingClosures {
  std::unique_ptr<hs::closures::DragClosure> drag;
  std::unique_ptr<hs::closures::LiftClosure> lift;
  std::unique_ptr<hs::closures::DeformationClosure> deformation;
};

/// Momentum bookkeeping of the last CFD step, N s (sums over all particles / cells).
struct ExchangeStats {
  hs::common::Vec3 drag_impulse_particles_N_s{};   // sum of the DEM's exact drag impulses J
  hs::common::Vec3 explicit_to_fluid_N_s{};        // sum_c f_c V_c dt given to the fluid explicitly
  hs::common::Vec3 received_by_fluid_N_s{};        // what the fluid's exchange terms gave it in the step
  hs::common::Vec3 pending_N_s{};                  // cumulative (received + J): given back next step
  double lost_solid_volume_m3 = 0.0;               // dropped by the eps_min clipping
};

/// On z-slabs (the fluid's grid and the DEM both on the same slabs, docs/cfd-dem.md "Distributed CFD-DEM" step 4)
/// each block deposits the markers in its cells (DividedMap), samples the fluid at the particles centred in its cells
/// (owned or remote ghosts) and sends the results to their owners, and sums the exchange bookkeeping over the ranks;
/// every member is then collective. Not yet on slabs (ConfigError): the channel frame.
/// One coupled step (CFDEM order): particles -> grid (divided map, eps, Us, Ksl), fluid at the particles
/// (velocity, gradient, pressure gradient, viscous force), per-particle forces (pressure gradient, viscous and
/// lift explicit, drag implicit with beta = 3 pi mu d_p correction K_wall), n_coupling DEM steps, the exchange of the
/// DEM's drag impulse to the fluid, then one PISO step.
class CfdDemCoupling {
 public:
  CfdDemCoupling(FvmSolver& fluid, DemSystem& dem, CouplingSettings settings, CouplingClosures closures);

  /// One coupled step: the four stages below in this order (the case skeleton times them one by one and may run
  /// its own between them, e.g. cells in and out after the DEM sub-steps).
  void step() {
    dem_substeps();
    particles_to_grid();
    fluid_step();
    fluid_to_particles();
  }
  /// Stage 1: the n_coupling DEM steps under the forces of the last step (computed first on the first step).
  void dem_substeps();
  /// Stage 2: the particles on the grid (divided map, eps, Us, Ksl) and their drag impulse given to the fluid.
  /// Particles added or removed since stage 1 are taken as they are now.
  void particles_to_grid();
  /// Stage 3: one PISO (or projection) step of the fluid, then the exchange bookkeeping; counts the step.
  void fluid_step();
  /// Stage 4: the fluid at the particles and the forces of the next step (pressure gradient, viscous, lift, drag).
  void fluid_to_particles() { particle_forces(); }
  [[nodiscard]] const ExchangeStats& exchange() const { return stats_; }
  [[nodiscard]] const DividedMap& map() const { return map_; }
  [[nodiscard]] long steps() const { return steps_; }
  /// DEM steps taken by the last CFD step, and over the run (since construction or the restart).
  [[nodiscard]] int last_substeps() const { return last_substeps_; }
  [[nodiscard]] long total_substeps() const { return total_substeps_; }
  /// The drag-limited step computed at the start of the last CFD step (drag_limited mode only).
  [[nodiscard]] const DragLimitedStep& last_drag_limited_step() const { return last_drag_limited_; }
  /// Mean axial velocity u_av of u_r+ in the tube frame (set by the case; until set, u_r+ = 0). The channel frame
  /// measures it at every sphere instead.
  void set_mean_velocity_m_s(double u_av) { mean_velocity_m_s_ = u_av; }
  /// Total momentum of the fluid (rho sum eps u dx^3 over the active velocity nodes), kg m/s.
  [[nodiscard]] hs::common::Vec3 fluid_momentum_kg_m_s() const;
  /// Total momentum of the owned particles, kg m/s.
  [[nodiscard]] hs::common::Vec3 particle_momentum_kg_m_s() const;

  /// Restart (coupling_checkpoint.cpp): the fluid (names "fluid.*"), the particles ("dem.*") and the coupling's own
  /// state ("coupling.*": eps of the last refresh, lift reaction, exchange bookkeeping with the pending imbalance,
  /// mean velocity, step count) into one checkpoint, written after a step().
  void write_state(hs::common::Checkpoint& cp) const;
  /// Restores write_state() into a coupling built with the same case: the next step() continues the saved run
  /// (to round-off: the DEM re-sorts its particles at the restart, see dem_checkpoint.hpp).
  void read_state(const hs::common::Checkpoint& cp);

  /// The closures, for their usage counters (evaluations, how many had an input outside the validity box).
  [[nodiscard]] const CouplingClosures& closures() const { return closures_; }

 private:
  void particle_forces();
  /// On slabs (nothing on one rank), first thing in particles_to_grid: the remote ghosts' positions, velocities and
  /// the coupling columns the deposit reads (drag coefficient, drag impulse, lift) from their owners.
  void refresh_ghosts();
  /// Sums over the ranks on slabs (identity on one).
  [[nodiscard]] hs::common::Vec3 summed(hs::common::Vec3 v) const;
  [[nodiscard]] double summed(double x) const;
  [[nodiscard]] long summed(long n) const;
  void fill_fields();
  void exchange_drag();
  [[nodiscard]] hs::common::Vec3 received_by_fluid_N_s() const;
  /// The channel at a sphere: the lift's direction, R_c of gamma+ and the wall correction, u_av and the flow's
  /// direction of u_r+ (from the tube settings or the channel frame).
  struct LocalChannel {
    hs::common::Vec3 lift_direction;
    double radius_m;
    hs::common::Vec3 flow_direction;
    double mean_velocity_m_s;
  };
  [[nodiscard]] LocalChannel local_channel(const hs::common::Vec3& x);
  /// The particle columns the fluid's values at a particle go to.
  struct SampledColumns {
    ParticleStore::Vec3Columns& external_force_N;
    ParticleStore::Vec3Columns& fluid_velocity_m_s;
    ParticleStore::Vec3Columns& lift_force_N;
    ParticleStore::Vec3Columns& fluid_angular_velocity_rad_s;
    ParticleStore::Column& drag_coefficient_N_s_m;
    ParticleStore::Column& rotational_drag_N_m_s;
    ParticleStore::Column& deformation_index;
  };
  /// The fluid's values at particle i (owned, or on slabs a remote ghost centred here) written into its row of
  /// `out`; false with `message` set for a bad drag coefficient.
  bool sample_fluid_at(std::size_t i, bool correct, const std::vector<LocalChannel>& channels, SampledColumns& out,
                       std::string& message);
  [[nodiscard]] hs::closures::ClosureInputs inputs(std::size_t i, const hs::common::Vec3& uf,
                                                    const std::array<hs::common::Vec3, 3>& grad, double local_ht,
                                                    const LocalChannel& channel) const;
  /// The self-mobility table for spheres of this diameter, measured on first use; ConfigError for d_p > dx.
  [[nodiscard]] const SelfMobility& self_mobility(double diameter_m);
  /// buoyancy_density_ from the fluid's present pressure and stress (CouplingSettings::buoyancy_over_footprint).
  void fill_buoyancy_density();
  /// footprint_sum_: buoyancy_density_ summed over each particle's markers' cells (collective on slabs).
  void sum_over_footprints();

  FvmSolver& fluid_;
  DemSystem& dem_;
  DemSlabs* slabs_;   // the DEM's (null: one rank holds everything)
  CouplingSettings settings_;
  CouplingClosures closures_;
  DividedMap map_;
  BlockField<double> eps_old_;
  BlockField<hs::common::Vec3> lift_reaction_N_;   // minus the lift of the particles, per cell, N
  ExchangeStats stats_;
  double mean_velocity_m_s_ = 0.0;
  long steps_ = 0;
  int last_substeps_ = 0;
  long total_substeps_ = 0;
  DragLimitedStep last_drag_limited_;
  std::vector<SelfMobility> self_mobility_;   // one per sphere diameter in the run
  std::unique_ptr<ChannelFrame> channel_;       // the channel frame's memo (closure_frame = channel)
  bool located_since_dem_ = false;             // map_ located by fill_fields() and no DEM step since
  std::unique_ptr<DiffusionSmoothing> smoothing_;   // smoothing_length_m > 0
  std::unique_ptr<FvmGrid> whole_grid_;   // on slabs, for the self-mobility tables (self_induced_correction)
  BlockField<hs::common::Vec3> buoyancy_density_;   // buoyancy_over_footprint: -grad p + div tau at cell centres, N/m^3
  std::array<ParticleStore::Column, 3> footprint_sum_;   // per store row: its sum over the markers, N/m^3
  ParticleStore::Vec3Columns lift_before_;   // on slabs: the last step's lift while the sampled columns are cleared
};

}  // namespace hs::unresolved
