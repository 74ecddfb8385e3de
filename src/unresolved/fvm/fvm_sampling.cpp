// SPDX-License-Identifier: MIT
// FvmSolver: fluid quantities at arbitrary points and at cell centres (what the coupling and outputs read).
#include <algorithm>
#include <cmath>

#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

using hs::common::Vec3;

namespace {

/// A point's trilinear stencil on the block layout every field shares: the flat index of the first of the eight
/// corners and their weights, corner q at (q & 1, (q >> 1) & 1, q >> 2). One stencil serves every field whose values
/// sit at the same offsets (the three components of u and of div(tau) each have their own; p has its own).
struct Stencil {
  long base = 0;
  std::array<long, 3> stride{};
  std::array<double, 8> weight{};
};

/// The stencil at t (the point in cells from the block origin) for values at i + offset[a] along each axis a, the
/// position clamped to [-1, last[a]] and the lower corner to at most n[a] (the ghost layers each field has).
Stencil stencil_at(const std::array<double, 3>& t, const std::array<double, 3>& offset, const std::array<int, 3>& last,
                   const std::array<int, 3>& n, const BlockField<double>& layout) {
  std::array<int, 3> i0{};
  std::array<double, 3> w{};
  for (std::size_t a = 0; a < 3; ++a) {
    const double s = std::clamp(t[a] - offset[a], -1.0, static_cast<double>(last[a]));
    const int lo = std::min(static_cast<int>(std::floor(s)), n[a]);
    i0[a] = lo;
    w[a] = std::clamp(s - lo, 0.0, 1.0);
  }
  Stencil st;
  st.base = static_cast<long>(layout.index(i0[0], i0[1], i0[2]));
  st.stride = {1, layout.stride(1), layout.stride(2)};
  for (int q = 0; q < 8; ++q) {
    const int di = q & 1;
    const int dj = (q >> 1) & 1;
    const int dk = (q >> 2) & 1;
    st.weight[static_cast<std::size_t>(q)] =
        (di != 0 ? w[0] : 1.0 - w[0]) * (dj != 0 ? w[1] : 1.0 - w[1]) * (dk != 0 ? w[2] : 1.0 - w[2]);
  }
  return st;
}

/// The field at the stencil's point; corners of zero weight are skipped (a ghost beyond the last plane is never read).
double apply(const Stencil& st, const BlockField<double>& field) {
  double v = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double weight = st.weight[static_cast<std::size_t>(q)];
    if (weight == 0.0) continue;
    const long at = st.base + (q & 1) * st.stride[0] + ((q >> 1) & 1) * st.stride[1] + ((q >> 2) & 1) * st.stride[2];
    v += weight * field[static_cast<std::size_t>(at)];
  }
  return v;
}

}  // namespace

std::array<double, 3> FvmSolver::in_cells(const Vec3& wrapped_m) const {
  std::array<double, 3> t{};
  for (int a = 0; a < 3; ++a) t[static_cast<std::size_t>(a)] = (wrapped_m[a] - grid_.origin_m()[a]) / h_;
  return t;
}

/// Trilinear interpolation of the three staggered components (values at the face centres of their own axis) at a
/// point: one wrap and one stencil per component.
Vec3 FvmSolver::interpolate_components(const std::array<BlockField<double>, 3>& fields, const Vec3& x_m) const {
  const std::array<double, 3> t = in_cells(grid_.wrap(x_m));
  const std::array<int, 3>& n = grid_.cells();
  // A block's face field along z reaches the next block's second face (ghost plane n + 1): a point within half a
  // cell above the block (a velocity gradient's stencil) interpolates up to it instead of stopping at face n.
  const bool next_block = grid_.slabs() != nullptr && !grid_.slabs()->on_global_face(2, 1);
  Vec3 v;
  for (int c = 0; c < 3; ++c) {
    std::array<double, 3> offset{0.5, 0.5, 0.5};
    offset[static_cast<std::size_t>(c)] = 0.0;
    std::array<int, 3> last = n;
    if (c == 2 && next_block) last[2] = n[2] + 1;
    const BlockField<double>& f = fields[static_cast<std::size_t>(c)];
    v[c] = apply(stencil_at(t, offset, last, n, f), f);
  }
  return v;
}

Vec3 FvmSolver::velocity_at(const Vec3& x_m) const { return interpolate_components(u_, x_m); }

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

Vec3 FvmSolver::viscous_force_density_at(const Vec3& x_m) const { return interpolate_components(viscous_force_, x_m); }

Vec3 FvmSolver::pressure_gradient_at(const Vec3& x_m) const {
  Vec3 grad;
  const std::array<int, 3>& n = grid_.cells();
  // Trilinear interpolation of the cell-centred pressure: a node field offset by half a cell on every axis.
  const auto cell_p = [&](const Vec3& y) { return apply(stencil_at(in_cells(grid_.wrap(y)), {0.5, 0.5, 0.5}, n, n, p_), p_); };
  // Face-normal gradients live on the velocity nodes: interpolate them as node fields.
  const Vec3 x = grid_.wrap(x_m);
  for (int c = 0; c < 3; ++c) {
    Vec3 lo = x;
    Vec3 hi = x;
    lo[c] -= 0.5 * h_;
    hi[c] += 0.5 * h_;
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
