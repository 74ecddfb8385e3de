// SPDX-License-Identifier: MIT
// Optical-tweezers stretching: patch selection, force application and the march to steady state.
#include "resolved/membrane/stretching_experiment.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hs::resolved {
namespace {

using hs::common::Vec3;

/// Vertices on the `sign` side within the contact radius of the x axis; at least the most extreme vertex.
std::vector<int> end_patch(const TriangleMesh& mesh, double sign, double radius_m) {
  std::vector<int> patch;
  int extreme = 0;
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Vec3& p = mesh.vertices_m[i];
    if (sign * p.x > sign * mesh.vertices_m[extreme].x) extreme = i;
    if (sign * p.x > 0.0 && p.y * p.y + p.z * p.z <= radius_m * radius_m) patch.push_back(i);
  }
  if (patch.empty()) patch.push_back(extreme);
  return patch;
}

/// The steady state solves grad E(x) = F whatever the deformation friction (it only shapes the transient, and with
/// the default each long quasi-static step would keep a small fraction of its deformation: many more steps).
MembraneParameters quasi_static(MembraneParameters m) {
  m.deformation_friction_Pa_s_m = 0.0;
  return m;
}

}  // namespace

StretchingExperiment::StretchingExperiment(const TriangleMesh& rest_mesh, const MembraneParameters& material,
                                           const NpfemSettings& settings, const StretchingSetup& setup)
    : solver_(std::make_unique<NpfemSolver>(rest_mesh, quasi_static(material), settings, setup.time_step_s)),
      setup_(setup),
      patch_plus_(end_patch(rest_mesh, 1.0, 0.5 * setup.contact_diameter_m)),
      patch_minus_(end_patch(rest_mesh, -1.0, 0.5 * setup.contact_diameter_m)),
      rest_areas_(vertex_areas_m2(rest_mesh)) {}

StretchingPoint StretchingExperiment::run_force(double force_N) {
  std::vector<Vec3> forces(static_cast<std::size_t>(solver_->vertex_count()));
  for (const auto* patch : {&patch_plus_, &patch_minus_}) {
    const double sign = patch == &patch_plus_ ? 1.0 : -1.0;
    double total_area = 0.0;
    for (const int v : *patch) total_area += rest_areas_[v];
    for (const int v : *patch) forces[v] = Vec3{sign * force_N * rest_areas_[v] / total_area, 0.0, 0.0};
  }
  solver_->set_external_forces_N(forces);
  StretchingPoint point;
  point.force_N = force_N;
  const long iterations0 = solver_->statistics().iterations;
  const long unconverged0 = solver_->statistics().unconverged_steps;
  double prev_axial = -1.0;
  double prev_transverse = -1.0;
  for (int s = 0; s < setup_.max_steps_per_force; ++s) {
    (void)solver_->step();
    ++point.steps;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Vec3& p : solver_->positions_m()) {
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
    point.axial_m = xmax - xmin;
    point.transverse_m = ymax - ymin;
    if (std::abs(point.axial_m - prev_axial) < setup_.steady_tolerance_m &&
        std::abs(point.transverse_m - prev_transverse) < setup_.steady_tolerance_m) {
      point.steady = true;
      break;
    }
    prev_axial = point.axial_m;
    prev_transverse = point.transverse_m;
  }
  point.area_change = solver_->area_m2() / solver_->rest_area_m2() - 1.0;
  point.volume_change = solver_->volume_m3() / solver_->rest_volume_m3() - 1.0;
  point.iterations = solver_->statistics().iterations - iterations0;
  point.unconverged_steps = solver_->statistics().unconverged_steps - unconverged0;
  return point;
}

}  // namespace hs::resolved
