// SPDX-License-Identifier: MIT
// The regularised delta functions of the immersed boundary method: 2-, 3- and 4-point kernels and the
// tensor-product stencil of lattice nodes and weights around one Lagrangian marker.
#pragma once

#include <array>
#include <string>

#include "common/vec3.hpp"

namespace hs::resolved {

enum class DeltaKernel { two_point, three_point, four_point };

/// "2", "3" or "4" point; anything else throws std::invalid_argument.
DeltaKernel delta_kernel_from_points(int points);
int support_points(DeltaKernel kernel);

/// One-dimensional kernel phi(r), r in lattice units. All three satisfy sum_j phi(r - j) = 1 and
/// sum_j (r - j) phi(r - j) = 0 for every r (zeroth and first discrete moments), so interpolation of a linear
/// field is exact and spreading conserves force and torque.
///  - two_point:  phi2(r) = 1 - |r| for |r| <= 1 (linear hat).
///  - three_point (Roma, Peskin & Berger 1999): (1 + sqrt(1 - 3 r^2))/3 for |r| <= 1/2;
///                (5 - 3|r| - sqrt(1 - 3(1 - |r|)^2))/6 for 1/2 <= |r| <= 3/2.
///  - four_point (Peskin 2002, cosine-free; used by Palabos-npFEM, resolved-methods.md 2.1):
///                (3 - 2|r| + sqrt(1 + 4|r| - 4 r^2))/8 for |r| <= 1; (5 - 2|r| - sqrt(-7 + 12|r| - 4 r^2))/8 for 1 <= |r| <= 2.
double delta_1d(DeltaKernel kernel, double r);

/// Lattice nodes and weights around a marker at x_lu (lattice coordinates, node i at coordinate i).
/// pre: the stencil's nodes exist in the caller's index space (ghost layers wide enough, or periodic wrap).
/// post: weights sum to 1 (to round-off); base + k, k in [0, points), are the nodes along each axis.
struct DeltaStencil {
  std::array<int, 3> base{};
  int points = 0;
  std::array<std::array<double, 4>, 3> weight{};   // weight[axis][k]

  [[nodiscard]] double w(int i, int j, int k) const { return weight[0][static_cast<std::size_t>(i)] * weight[1][static_cast<std::size_t>(j)] * weight[2][static_cast<std::size_t>(k)]; }
};
DeltaStencil delta_stencil(DeltaKernel kernel, const common::Vec3& x_lu);

}  // namespace hs::resolved
