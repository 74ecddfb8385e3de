// SPDX-License-Identifier: MIT
// How far multi-direct forcing converges on the RBC's markers (258 vertices at dx = 1 um, 2-point kernel, the shear and
// tube cases): the slip left and the force spread after 1 ... 80 iterations, for issue #26's knob check (the DI moved
// with the IBM iterations). Prints the table; docs/resolved-coupling.md, "The IBM iterations and the DI".
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "resolved/ibm/immersed_boundary.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"
#include "resolved/membrane/triangle_mesh.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

struct ForcingOutcome {
  double slip_rms = 0.0;     // sqrt(mean |U - u|^2) at the markers after the forcing
  double slip_max = 0.0;
  double force_rms = 0.0;    // sqrt(mean |F_k|^2), F_k the force marker k spread (summed over the iterations)
  Vec3 net_force;            // sum_k F_k
};

/// Markers of the rest cell (disc axis along y, as the shear case) at rest in a 20^3 periodic box whose fluid moves
/// in simple shear u_x = g (y - y_c) about the cell's centre: the slip of a cell that does not follow the flow.
ForcingOutcome force_once(int iterations) {
  const int n = 20;
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {n, n, n}, .periodic = {true, true, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = 1.0}},
      MPI_COMM_WORLD);
  lattice->enable_force_field();
  const double g = 0.004;   // lattice shear rate: the cell's rim (3.9 lu) sees 0.016 lu/step, the case's order
  const Vec3 c{9.7, 10.2, 9.9};
  lattice->initialize([&](const Vec3& p) { return NodeInit{.rho_lu = 1.0, .u_lu = {g * (p.y - c.y), 0.0, 0.0}}; });
  TriangleMesh mesh = make_rbc_mesh({});   // um: 1 lu at dx = 1 um
  const auto area_m2 = vertex_areas_m2(mesh);
  Markers m;
  for (std::size_t k = 0; k < mesh.vertices_m.size(); ++k) {
    const Vec3 v = mesh.vertices_m[k] * 1e6;
    m.x_lu.push_back(c + Vec3{v.x, -v.z, v.y});   // disc axis z -> y
    m.u_lu.push_back({});
    m.area_lu.push_back(area_m2[k] * 1e12);
  }
  ImmersedBoundary ibm(*lattice, {.kernel = DeltaKernel::two_point, .iterations = iterations, .measure_slip = false});
  const ForcingReport report = ibm.apply(m);
  const MarkerFluid after = ibm.interpolate(m.x_lu);
  ForcingOutcome out;
  for (std::size_t k = 0; k < m.x_lu.size(); ++k) {
    const double s = common::norm(after.u_lu[k] - m.u_lu[k]);
    out.slip_rms += s * s;
    out.slip_max = std::max(out.slip_max, s);
    out.force_rms += common::dot(report.marker_force_lu[k], report.marker_force_lu[k]);
    out.net_force += report.marker_force_lu[k];
  }
  out.slip_rms = std::sqrt(out.slip_rms / static_cast<double>(m.x_lu.size()));
  out.force_rms = std::sqrt(out.force_rms / static_cast<double>(m.x_lu.size()));
  return out;
}

TEST(ForcingConvergence, NetForceConvergesWhileTheMarkersForcesDoNot) {
  std::printf("[ibm-rbc] iterations | slip rms / g a | slip max / g a | marker force rms | net force x\n");
  const double scale = 0.004 * 3.91;
  const std::vector<int> iterations{1, 2, 5, 10, 20, 40, 80};
  std::vector<ForcingOutcome> o;
  for (const int it : iterations) {
    o.push_back(force_once(it));
    std::printf("[ibm-rbc] %3d | %.4e | %.4e | %.5e | %.5e\n", it, o.back().slip_rms / scale, o.back().slip_max / scale,
                o.back().force_rms, o.back().net_force.x);
  }
  // Measured: slip rms 0.084, 0.044, 0.021, 0.016, 0.013, 0.010, 0.008 of g a: after the first few iterations it falls
  // only as ~N^-1/3, not geometrically; the marker force rms grows without bound (6.9e-3 at 5, 7.6e-3 at 10, 8.8e-3
  // at 20, 1.1e-2 at 40, 1.5e-2 at 80) while the net force settles within 3 % from 5 iterations on. 258 markers ~0.7 lu
  // apart under a 2 lu kernel are more than the lattice can tell apart: the interpolation-spreading operator has
  // eigenvalues near 0, and the forces along them grow by a constant each iteration and barely reach the fluid.
  for (std::size_t i = 1; i < o.size(); ++i) EXPECT_LT(o[i].slip_rms, o[i - 1].slip_rms) << iterations[i];
  // What the fluid feels converges: the net force from 5 iterations on within 5 % of 80 iterations' (measured 3 %).
  for (std::size_t i = 2; i < o.size(); ++i) {
    EXPECT_NEAR(o[i].net_force.x, o.back().net_force.x, 0.05 * std::abs(o.back().net_force.x)) << iterations[i];
  }
}

}  // namespace
}  // namespace hs::resolved
