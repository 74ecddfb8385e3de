// SPDX-License-Identifier: MIT
// One membrane immersed in the lattice fluid: the coupled time step of Palabos-npFEM (resolved-methods.md 2.3).
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "common/units/unit_converter.hpp"
#include "common/vec3.hpp"
#include "resolved/ibm/fluid_traction.hpp"
#include "resolved/ibm/immersed_boundary.hpp"
#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

/// What the membrane receives from the fluid (docs/resolved-coupling.md, "Momentum-consistent coupling").
///  fluid_stress: the fluid stress sampled outside the membrane (fluid_traction, Palabos-npFEM). The IBM force on the
///    fluid and this force are not equal and opposite: fluid + membrane momentum is not conserved.
///  ibm_reaction: minus the force every marker spread onto the fluid over the lattice steps of the previous membrane
///    interval (all direct-forcing iterations), averaged over the interval (Peskin 2002; Kruger 2011): the impulse the
///    membrane gets over its step h = k dt equals minus the impulse the fluid got, so the total is conserved.
enum class MembraneForce { fluid_stress, ibm_reaction };

struct CouplingSettings {
  IbmSettings ibm;
  int membrane_every = 2;          // lattice steps per membrane step, h = k dt (Palabos timestep_ShapeOp = 2)
  bool median_filter = true;       // Palabos-npFEM FILTERING is on (resolved-methods.md 1.4 step 6); fluid_stress only
  MembraneForce membrane_force = MembraneForce::fluid_stress;
  TractionArea traction_area = TractionArea::scaled_membrane;   // see fluid_traction.hpp
  common::Vec3 lattice_origin_m;   // SI position of global lattice node (0, 0, 0)
  /// Add the body-force drive on the volume the sampling surface encloses (cell + shell out to the sample nodes) to
  /// the membrane's force. The tractions are read 1-3 lu outside the membrane, so they miss that share of a body-force
  /// drive, and a free cell lagged (docs/resolved-coupling.md, "Open issues" 1). Off by default until re-measured.
  /// Ignored with MembraneForce::ibm_reaction: the reaction already carries the drive on the fluid inside the cell.
  bool drive_on_enclosed_volume = false;
  /// Optional forces added to the fluid traction before each membrane step, e.g. a membrane-wall repulsion:
  /// (vertex positions in SI, unwrapped; the external forces in newtons, to add to). Empty: none.
  std::function<void(std::span<const common::Vec3>, std::vector<common::Vec3>&)> add_forces_N{};
};

/// Diagnostics of the last coupled step.
struct CouplingReport {
  ForcingReport forcing;
  common::Vec3 fluid_force_N;      // sum of the external forces given to the membrane at its last step
  std::vector<common::Vec3> fluid_forces_N;   // per vertex, the fluid's force on the membrane at its last step
                                              // (before add_forces_N: no wall contact): the cell's stresslet
  double marker_drift_lu = 0.0;    // max |marker - npFEM vertex| before the snap at the end of an interval
  int vertices_without_fluid = 0;
  double sample_distance_lu = 0.0; // mean distance of the stress samples outside the membrane
};

/// The state the coupling adds to the fluid and membrane (for checkpoints).
struct CouplingState {
  std::vector<common::Vec3> marker_x_lu;
  std::vector<common::Vec3> marker_u_lu;
  long steps = 0;
  /// ibm_reaction: the per-marker force spread onto the fluid since the last membrane step (lattice units, summed
  /// over lattice steps and iterations): impulse the fluid has received and the membrane not yet. Empty: none.
  std::vector<common::Vec3> reaction_lu;
};

/// Runs the coupled step as named stages (STYLE R8), every lattice step:
///  1. membrane_solve (every k-th step): external force from the fluid stress at time t (fluid_traction,
///     converted to newtons) or, with ibm_reaction, minus the IBM force of the k lattice steps before, divided by k;
///     one npFEM step of length h = k dt; markers are not moved yet.
///  2. ibm_forcing: multi-direct forcing with the markers' (X, U) at time t.
///  3. lbm_step: collide, stream, halos, boundaries.
///  4. markers_advect: after a membrane step the markers take the new npFEM velocity; X += U every step, and at
///     the end of each interval X is set to the npFEM positions (which x^{n+1} = x^n + h v^{n+1} makes a no-op
///     up to round-off and the centre constraint).
/// The solver's time step must equal k dt. Every rank holds the whole membrane (deterministic, replicated).
class CoupledCell {
 public:
  CoupledCell(FluidLattice& lattice, NpfemSolver& membrane, const common::UnitConverter& units,
              const CouplingSettings& settings);

  void membrane_solve();
  void ibm_forcing();
  /// The markers' state this step (a suspension concatenates every cell's markers into one forcing pass).
  [[nodiscard]] const Markers& markers() const { return markers_; }
  /// Takes the forcing this cell's markers got from a forcing pass done elsewhere (CellSuspension: one pass over all
  /// cells' markers); ibm_forcing() is take_forcing(its own pass).
  void take_forcing(ForcingReport forcing);
  void lbm_step();
  void markers_advect();
  /// All four stages (tests; the cases add the stages to a TimeLoop to time them).
  void step();

  [[nodiscard]] const CouplingReport& report() const { return report_; }
  [[nodiscard]] long steps() const { return steps_; }
  /// The coming lattice step starts a membrane interval (membrane_solve() steps the membrane in it).
  [[nodiscard]] bool interval_starts() const { return steps_ % settings_.membrane_every == 0; }
  /// Marker positions in SI (unwrapped).
  [[nodiscard]] std::vector<common::Vec3> marker_positions_m() const;
  [[nodiscard]] CouplingState state() const { return {markers_.x_lu, markers_.u_lu, steps_, reaction_lu_}; }
  void restore(const CouplingState& state);

 private:
  [[nodiscard]] std::vector<common::Vec3> membrane_positions_lu() const;
  /// The membrane's force this step, newtons per vertex: the sampled fluid stress, or minus the IBM force.
  [[nodiscard]] std::vector<common::Vec3> stress_force_N();
  [[nodiscard]] std::vector<common::Vec3> reaction_force_N();

  FluidLattice& lattice_;
  NpfemSolver& membrane_;
  const common::UnitConverter& units_;
  CouplingSettings settings_;
  ImmersedBoundary ibm_;
  std::vector<std::vector<int>> ring_;
  Markers markers_;
  std::vector<common::Vec3> next_u_lu_;   // npFEM velocity of the current interval, copied after the LB step
  std::vector<common::Vec3> reaction_lu_; // ibm_reaction: IBM force per marker summed since the last membrane step
  CouplingReport report_;
  long steps_ = 0;
};

}  // namespace hs::resolved
