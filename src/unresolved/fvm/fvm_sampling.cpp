// SPDX-License-Identifier: MIT
// FvmSolver: fluid quantities at arbitrary points and at cell centres (what the coupling and outputs read).
#include <algorithm>
#include <cmath>

#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

using hs::common::Vec3;

/// Trilinear interpolation of a staggered node field of component c (values at face centres of c).
double FvmSolver::interpolate(int c, const BlockField<double>& field, const Vec3& x_m) const {
  const Vec3 x = grid_.wrap(x_m);
  std::array<int, 3> i0{};
  std::array<double, 3> w{};
  for (int a = 0; a < 3; ++a) {
    const int n = grid_.cells()[static_cast<std::size_t>(a)];
    double s = (x[a] - grid_.origin_m()[a]) / h_ - (a == c ? 0.0 : 0.5);
    // A block's face field along z reaches the next block's second face (ghost plane n + 1): a point within half a
    // cell above the block (a velocity gradient's stencil) interpolates up to it instead of stopping at face n.
    const bool next_block = a == c && a == 2 && grid_.slabs() != nullptr && !grid_.slabs()->on_global_face(2, 1);
    s = std::clamp(s, -1.0, static_cast<double>(next_block ? n + 1 : n));
    const int lo = std::min(static_cast<int>(std::floor(s)), n);
    i0[static_cast<std::size_t>(a)] = lo;
    w[static_cast<std::size_t>(a)] = std::clamp(s - lo, 0.0, 1.0);
  }
  double v = 0.0;
  for (int q = 0; q < 8; ++q) {
    const int di = q & 1;
    const int dj = (q >> 1) & 1;
    const int dk = (q >> 2) & 1;
    const double weight = (di != 0 ? w[0] : 1.0 - w[0]) * (dj != 0 ? w[1] : 1.0 - w[1]) * (dk != 0 ? w[2] : 1.0 - w[2]);
    if (weight == 0.0) continue;
    v += weight * field(i0[0] + di, i0[1] + dj, i0[2] + dk);
  }
  return v;
}

Vec3 FvmSolver::velocity_at(const Vec3& x_m) const {
  return {interpolate(0, u_[0], x_m), interpolate(1, u_[1], x_m), interpolate(2, u_[2], x_m)};
}

std::array<Vec3, 3> FvmSolver::velocity_gradient_at(const Vec3& x_m) const {
  std::array<Vec3, 3> g{};
  for (int b = 0; b < 3; ++b) {
    Vec3 d;
    d[b] = 0.5 * h_;
    const Vec3 up = velocity_at(x_m + d);
    const Vec3 down = velocity_at(x_m - d);
    for (int a = 0; a < 3; ++a) g[static_cast<std::size_t>(a)][b] = (up[a] - down[a]) / h_;
  }
  return g;
}

Vec3 FvmSolver::viscous_force_density_at(const Vec3& x_m) const {
  return {interpolate(0, viscous_force_[0], x_m), interpolate(1, viscous_force_[1], x_m),
          interpolate(2, viscous_force_[2], x_m)};
}

Vec3 FvmSolver::pressure_gradient_at(const Vec3& x_m) const {
  Vec3 grad;
  // Face-normal gradients live on the velocity nodes: interpolate them as node fields.
  for (int c = 0; c < 3; ++c) {
    const Vec3 x = grid_.wrap(x_m);
    Vec3 lo = x;
    Vec3 hi = x;
    lo[c] -= 0.5 * h_;
    hi[c] += 0.5 * h_;
    auto cell_p = [&](const Vec3& y) {
      // Trilinear interpolation of the cell-centred pressure: a node field of "component -1".
      std::array<int, 3> i0{};
      std::array<double, 3> w{};
      const Vec3 yw = grid_.wrap(y);
      for (int a = 0; a < 3; ++a) {
        const int n = grid_.cells()[static_cast<std::size_t>(a)];
        const double s = std::clamp((yw[a] - grid_.origin_m()[a]) / h_ - 0.5, -1.0, static_cast<double>(n));
        const int l = std::min(static_cast<int>(std::floor(s)), n);
        i0[static_cast<std::size_t>(a)] = l;
        w[static_cast<std::size_t>(a)] = std::clamp(s - l, 0.0, 1.0);
      }
      double v = 0.0;
      for (int q = 0; q < 8; ++q) {
        const int di = q & 1;
        const int dj = (q >> 1) & 1;
        const int dk = (q >> 2) & 1;
        v += (di != 0 ? w[0] : 1.0 - w[0]) * (dj != 0 ? w[1] : 1.0 - w[1]) * (dk != 0 ? w[2] : 1.0 - w[2]) *
             p_(i0[0] + di, i0[1] + dj, i0[2] + dk);
      }
      return v;
    };
    grad[c] = (cell_p(hi) - cell_p(lo)) / h_;
  }
  grad[drive_.axis] += drive_gradient_;
  return fluid_.density_kg_m3 * grad;
}

Vec3 FvmSolver::cell_velocity(int i, int j, int k) const {
  Vec3 v;
  for (int c = 0; c < 3; ++c) {
    const auto& u = u_[static_cast<std::size_t>(c)];
    std::array<int, 3> hi{i, j, k};
    hi[static_cast<std::size_t>(c)] += 1;
    v[c] = 0.5 * (u(i, j, k) + u(hi[0], hi[1], hi[2]));
  }
  return v;
}

double FvmSolver::cell_pressure_Pa(int i, int j, int k) const {
  const Vec3 x = grid_.cell_centre_m(i, j, k);
  const double corner = grid_.box_m().lo[drive_.axis];
  return fluid_.density_kg_m3 * (p_(i, j, k) + p_level_kin_ + drive_gradient_ * (x[drive_.axis] - corner));
}

}  // namespace hs::unresolved
