// SPDX-License-Identifier: MIT
// Optical-tweezers stretching of one RBC (Mills et al. 2004): opposite forces on two end patches, steady state.
#pragma once

#include <memory>
#include <vector>

#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

struct StretchingSetup {
  /// Bead contact diameter: ~2 um in Mills et al. 2004 (Mech Chem Biosyst 1:169).
  double contact_diameter_m = 2.0e-6;
  /// Membrane step. The steady state does not depend on it (implicit Euler is unconditionally stable), so a long
  /// quasi-static step reaches it in few steps.
  double time_step_s = 1.0e-4;
  int max_steps_per_force = 200;
  /// Steady when both diameters change by less than this between steps, m.
  double steady_tolerance_m = 1.0e-10;
};

struct StretchingPoint {
  double force_N = 0.0;
  double axial_m = 0.0;          // extent along the force (x)
  double transverse_m = 0.0;     // in-plane extent across the force (y)
  double area_change = 0.0;      // (A - A0)/A0
  double volume_change = 0.0;    // (V - V0)/V0
  int steps = 0;
  long iterations = 0;
  long unconverged_steps = 0;
  bool steady = false;
};

/// The cell lies in the x-y plane (axis of symmetry z) and is pulled along x. Force levels are applied in the
/// order asked, each starting from the previous steady state (as in the experiment, loading upward).
class StretchingExperiment {
 public:
  StretchingExperiment(const TriangleMesh& rest_mesh, const MembraneParameters& material, const NpfemSettings& settings,
                       const StretchingSetup& setup);

  /// Applies +F/-F (area-weighted over each patch) and steps to the steady state.
  StretchingPoint run_force(double force_N);
  [[nodiscard]] const NpfemSolver& solver() const { return *solver_; }
  [[nodiscard]] int patch_vertex_count() const { return static_cast<int>(patch_plus_.size()); }

 private:
  std::unique_ptr<NpfemSolver> solver_;
  StretchingSetup setup_;
  std::vector<int> patch_plus_;
  std::vector<int> patch_minus_;
  std::vector<double> rest_areas_;
};

}  // namespace hs::resolved
