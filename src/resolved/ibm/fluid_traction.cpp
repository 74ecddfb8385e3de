// SPDX-License-Identifier: MIT
// The membrane's external force from the fluid stress (Palabos-npFEM, resolved-methods.md 1.4 steps 1-6).
#include "resolved/ibm/fluid_traction.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include <mpi.h>

namespace hs::resolved {

std::vector<std::vector<int>> one_ring(int vertex_count, std::span<const std::array<int, 3>> triangles) {
  std::vector<std::set<int>> sets(static_cast<std::size_t>(vertex_count));
  for (const auto& t : triangles) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        if (a != b) sets[static_cast<std::size_t>(t[static_cast<std::size_t>(a)])].insert(t[static_cast<std::size_t>(b)]);
      }
    }
  }
  std::vector<std::vector<int>> ring(sets.size());
  for (std::size_t v = 0; v < sets.size(); ++v) ring[v].assign(sets[v].begin(), sets[v].end());
  return ring;
}

std::vector<common::Vec3> median_filter(std::span<const common::Vec3> values, const std::vector<std::vector<int>>& ring) {
  if (ring.size() != values.size()) throw std::invalid_argument("median_filter: one ring per value");
  std::vector<common::Vec3> out(values.size());
  std::vector<double> window;
  for (std::size_t v = 0; v < values.size(); ++v) {
    for (int a = 0; a < 3; ++a) {
      window.assign(1, values[v][a]);
      for (int nb : ring[v]) window.push_back(values[static_cast<std::size_t>(nb)][a]);
      const auto mid = window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2);
      std::nth_element(window.begin(), mid, window.end());
      double m = *mid;
      if (window.size() % 2 == 0) m = 0.5 * (m + *std::max_element(window.begin(), mid));
      out[v][a] = m;
    }
  }
  return out;
}

namespace {

/// The stencil node (global coordinates, unwrapped) with the largest projection of its offset on the normal.
std::array<int, 3> outermost_node(DeltaKernel kernel, const common::Vec3& x, const common::Vec3& n) {
  const DeltaStencil s = delta_stencil(kernel, x);
  std::array<int, 3> best{};
  double best_projection = -1e300;
  for (int k = 0; k < s.points; ++k)
    for (int j = 0; j < s.points; ++j)
      for (int i = 0; i < s.points; ++i) {
        const std::array<int, 3> g{s.base[0] + i, s.base[1] + j, s.base[2] + k};
        const double p = common::dot(common::Vec3{double(g[0]), double(g[1]), double(g[2])} - x, n);
        if (p > best_projection) {
          best_projection = p;
          best = g;
        }
      }
  return best;
}

constexpr std::size_t kSlots = 5;   // shear force (3), pressure, found-fluid flag

}  // namespace

TractionResult fluid_traction(const ImmersedBoundary& ibm, const FluidLattice& lattice, const SurfaceSample& surface,
                              const std::vector<std::vector<int>>& ring) {
  const std::size_t nv = surface.x_lu.size();
  if (surface.normal.size() != nv || surface.area_lu.size() != nv) throw std::invalid_argument("fluid_traction: sizes differ");
  std::vector<double> slots(kSlots * nv, 0.0);
  std::array<int, 3> local{};
  for (std::size_t v = 0; v < nv; ++v) {
    const std::array<int, 3> g = outermost_node(ibm.settings().kernel, surface.x_lu[v], surface.normal[v]);
    if (!ibm.to_local(g, local) || !lattice.is_fluid(local[0], local[1], local[2])) continue;
    const SymTensor s = lattice.viscous_stress(local[0], local[1], local[2]);
    const common::Vec3& n = surface.normal[v];
    const common::Vec3 sn{s[0] * n.x + s[3] * n.y + s[4] * n.z, s[3] * n.x + s[1] * n.y + s[5] * n.z,
                          s[4] * n.x + s[5] * n.y + s[2] * n.z};
    for (int a = 0; a < 3; ++a) slots[kSlots * v + static_cast<std::size_t>(a)] = surface.area_lu[v] * sn[a];
    slots[kSlots * v + 3] = lattice.moments(local[0], local[1], local[2]).rho / 3.0;   // p = c_s^2 rho
    slots[kSlots * v + 4] = 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, slots.data(), static_cast<int>(slots.size()), MPI_DOUBLE, MPI_SUM,
                lattice.decomposition().comm());
  TractionResult result;
  double pa = 0.0;
  double a_sum = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    if (slots[kSlots * v + 4] == 0.0) continue;
    pa += slots[kSlots * v + 3] * surface.area_lu[v];
    a_sum += surface.area_lu[v];
  }
  result.mean_pressure_lu = a_sum > 0.0 ? pa / a_sum : 0.0;
  result.force_lu.assign(nv, {});
  for (std::size_t v = 0; v < nv; ++v) {
    if (slots[kSlots * v + 4] == 0.0) {
      ++result.vertices_without_fluid;
      continue;
    }
    const common::Vec3 shear{slots[kSlots * v], slots[kSlots * v + 1], slots[kSlots * v + 2]};
    const double dp = slots[kSlots * v + 3] - result.mean_pressure_lu;
    result.force_lu[v] = shear - dp * surface.area_lu[v] * surface.normal[v];
  }
  if (!ring.empty()) result.force_lu = median_filter(result.force_lu, ring);
  return result;
}

}  // namespace hs::resolved
