// SPDX-License-Identifier: MIT
// A uniform grid of linked cells over a box, used to sort particles and to find neighbour candidates.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "common/vec3.hpp"

namespace hs::unresolved {

class CellGrid {
 public:
  /// Cells of edge >= min_cell_m covering [lo, hi]; points outside are put in the nearest boundary cell.
  /// At most about max_cells cells: a sparse system in a large box gets larger cells instead of empty memory.
  CellGrid(const hs::common::Vec3& lo_m, const hs::common::Vec3& hi_m, double min_cell_m, double max_cells = 1e9)
      : lo_(lo_m) {
    double cell = min_cell_m;
    for (int pass = 0; pass < 2; ++pass) {
      double count = 1.0;
      for (int a = 0; a < 3; ++a) {
        const double extent = hi_m[a] - lo_m[a];
        n_[a] = std::max(1, static_cast<int>(std::floor(extent / cell)));
        inv_cell_[a] = static_cast<double>(n_[a]) / std::max(extent, 1e-300);
        count *= n_[a];
      }
      if (count <= max_cells) break;
      cell *= std::cbrt(count / max_cells) * 1.01;
    }
  }

  [[nodiscard]] int cell_coord(int axis, double x_m) const {
    const int c = static_cast<int>(std::floor((x_m - lo_[axis]) * inv_cell_[axis]));
    return std::clamp(c, 0, n_[axis] - 1);
  }
  [[nodiscard]] int index(int cx, int cy, int cz) const { return (cz * n_[1] + cy) * n_[0] + cx; }
  [[nodiscard]] int index_of(double x_m, double y_m, double z_m) const {
    return index(cell_coord(0, x_m), cell_coord(1, y_m), cell_coord(2, z_m));
  }
  [[nodiscard]] int n(int axis) const { return n_[axis]; }
  [[nodiscard]] int n_cells() const { return n_[0] * n_[1] * n_[2]; }

 private:
  hs::common::Vec3 lo_;
  std::array<int, 3> n_{1, 1, 1};
  std::array<double, 3> inv_cell_{1.0, 1.0, 1.0};
};

}  // namespace hs::unresolved
