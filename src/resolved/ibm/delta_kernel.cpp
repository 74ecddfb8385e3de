// SPDX-License-Identifier: MIT
// The regularised delta functions of the immersed boundary method.
#include "resolved/ibm/delta_kernel.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::resolved {

DeltaKernel delta_kernel_from_points(int points) {
  switch (points) {
    case 2: return DeltaKernel::two_point;
    case 3: return DeltaKernel::three_point;
    case 4: return DeltaKernel::four_point;
    default: throw std::invalid_argument("IBM kernel: 2, 3 or 4 points");
  }
}

int support_points(DeltaKernel kernel) {
  switch (kernel) {
    case DeltaKernel::two_point: return 2;
    case DeltaKernel::three_point: return 3;
    case DeltaKernel::four_point: return 4;
  }
  return 0;
}

double delta_1d(DeltaKernel kernel, double r) {
  const double a = std::abs(r);
  switch (kernel) {
    case DeltaKernel::two_point: return a < 1.0 ? 1.0 - a : 0.0;
    case DeltaKernel::three_point:
      if (a <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * a * a)) / 3.0;
      if (a <= 1.5) return (5.0 - 3.0 * a - std::sqrt(std::max(0.0, 1.0 - 3.0 * (1.0 - a) * (1.0 - a)))) / 6.0;
      return 0.0;
    case DeltaKernel::four_point:
      if (a <= 1.0) return (3.0 - 2.0 * a + std::sqrt(1.0 + 4.0 * a - 4.0 * a * a)) / 8.0;
      if (a <= 2.0) return (5.0 - 2.0 * a - std::sqrt(std::max(0.0, -7.0 + 12.0 * a - 4.0 * a * a))) / 8.0;
      return 0.0;
  }
  return 0.0;
}

DeltaStencil delta_stencil(DeltaKernel kernel, const common::Vec3& x_lu) {
  DeltaStencil s;
  s.points = support_points(kernel);
  for (int d = 0; d < 3; ++d) {
    // First node of the support: for an even support the nodes straddle x symmetrically (floor - n/2 + 1);
    // for the 3-point kernel the nearest node is the centre (round - 1).
    const double x = x_lu[d];
    const int first = s.points == 3 ? static_cast<int>(std::lround(x)) - 1 : static_cast<int>(std::floor(x)) - s.points / 2 + 1;
    s.base[static_cast<std::size_t>(d)] = first;
    for (int k = 0; k < s.points; ++k) s.weight[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)] = delta_1d(kernel, static_cast<double>(first + k) - x);
  }
  return s;
}

}  // namespace hs::resolved
