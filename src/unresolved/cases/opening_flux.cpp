// SPDX-License-Identifier: MIT
#include "unresolved/cases/opening_flux.hpp"

#include <array>
#include <cmath>

#include <mpi.h>

namespace hs::unresolved {

double opening_outward_flux_m3_s(const FvmSolver& fluid, const hs::common::Opening& opening) {
  const FvmGrid& g = fluid.grid();
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (std::abs(opening.normal[a]) > std::abs(opening.normal[axis])) axis = a;
  }
  const double sign = opening.normal[axis] > 0.0 ? 1.0 : -1.0;
  const int layer = sign > 0.0 ? g.cells()[static_cast<std::size_t>(axis)] : 0;   // the box side's face layer
  const BlockField<double>& u = fluid.face_velocity(axis);
  const BlockField<double>& ap = g.apertures(axis);
  const BlockField<double>& eps = fluid.void_fraction();
  const double area = g.dx_m() * g.dx_m();
  const long stride = eps.stride(axis);
  double sum = 0.0;
  std::array<int, 3> n{g.node_count(axis, 0), g.node_count(axis, 1), g.node_count(axis, 2)};
  n[static_cast<std::size_t>(axis)] = 1;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        std::array<int, 3> node{i, j, k};
        node[static_cast<std::size_t>(axis)] = layer;
        if (opening.lateral_m(g.node_position_m(axis, node[0], node[1], node[2])) > opening.radius_m + g.dx_m()) continue;
        const std::size_t idx = u.index(node[0], node[1], node[2]);
        if (ap[idx] == 0.0) continue;
        const double e = 0.5 * (eps[idx - static_cast<std::size_t>(stride)] + eps[idx]);
        sum += e * ap[idx] * area * u[idx];
      }
    }
  }
  if (const auto* slabs = g.slabs()) {   // the whole opening: every block's share (a z-side is one block's)
    if (axis == 2 && !slabs->on_global_face(2, sign > 0.0 ? 1 : 0)) sum = 0.0;
    MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, slabs->comm());
  }
  return sign * sum;
}

}  // namespace hs::unresolved
