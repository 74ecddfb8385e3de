// SPDX-License-Identifier: MIT
// The short-range membrane-wall repulsion (linear contact spring along the wall normal).
#include "resolved/cases/wall_repulsion.hpp"

#include <cmath>
#include <stdexcept>

namespace hs::resolved {

WallRepulsion::WallRepulsion(const common::Shape& shape, const WallRepulsionSpec& spec) : shape_(shape), spec_(spec) {
  if (spec.range_m < 0.0 || spec.stiffness_N_m < 0.0 || spec.period_x_m < 0.0) {
    throw std::invalid_argument("WallRepulsion: range, stiffness and period must be >= 0");
  }
}

common::Vec3 WallRepulsion::wrapped(common::Vec3 p) const {
  if (spec_.period_x_m > 0.0) p.x -= spec_.period_x_m * std::floor(p.x / spec_.period_x_m);
  return p;
}

void WallRepulsion::add_forces(std::span<const common::Vec3> x_m, std::vector<common::Vec3>& forces_N) {
  last_total_N_ = 0.0;
  last_vertices_ = 0;
  if (!enabled()) return;
  if (forces_N.size() != x_m.size()) throw std::invalid_argument("WallRepulsion: one force per vertex");
  const double eps = 1e-3 * spec_.range_m;   // central-difference step of the normal
  for (std::size_t v = 0; v < x_m.size(); ++v) {
    const common::Vec3 p = wrapped(x_m[v]);
    const double d = -shape_.signed_distance(p);
    if (d >= spec_.range_m) continue;
    common::Vec3 n;
    for (int a = 0; a < 3; ++a) {
      common::Vec3 hi = p, lo = p;
      hi[a] += eps;
      lo[a] -= eps;
      n[a] = -(shape_.signed_distance(hi) - shape_.signed_distance(lo)) / (2.0 * eps);
    }
    const double len = common::norm(n);
    if (len == 0.0) continue;
    const double f = spec_.stiffness_N_m * (spec_.range_m - d);
    forces_N[v] += (f / len) * n;
    last_total_N_ += f;
    ++last_vertices_;
  }
}

}  // namespace hs::resolved
