// SPDX-License-Identifier: MIT
// The membrane's external force from the fluid stress (Palabos-npFEM, resolved-methods.md 1.4 steps 1-6).
#include "resolved/ibm/fluid_traction.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
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

std::vector<common::Vec3> offset_area_vectors(std::span<const common::Vec3> x, std::span<const common::Vec3> normal,
                                              std::span<const double> offset, std::span<const std::array<int, 3>> triangles) {
  if (normal.size() != x.size() || offset.size() != x.size()) throw std::invalid_argument("offset_area_vectors: sizes differ");
  std::vector<common::Vec3> moved(x.size());
  for (std::size_t v = 0; v < x.size(); ++v) moved[v] = x[v] + offset[v] * normal[v];
  std::vector<common::Vec3> area(x.size());
  for (const auto& t : triangles) {
    const common::Vec3& a = moved[static_cast<std::size_t>(t[0])];
    const common::Vec3 third = common::cross(moved[static_cast<std::size_t>(t[1])] - a,
                                             moved[static_cast<std::size_t>(t[2])] - a) / 6.0;
    for (int corner : t) area[static_cast<std::size_t>(corner)] += third;
  }
  return area;
}

namespace {

struct SampleNode {
  std::array<int, 3> node;   // global coordinates, unwrapped
  double distance;           // projection of its offset on the normal
};

/// The stencil node with the largest projection of its offset on the normal.
SampleNode outermost_node(DeltaKernel kernel, const common::Vec3& x, const common::Vec3& n) {
  const DeltaStencil s = delta_stencil(kernel, x);
  SampleNode best{{}, -1e300};
  for (int k = 0; k < s.points; ++k)
    for (int j = 0; j < s.points; ++j)
      for (int i = 0; i < s.points; ++i) {
        const std::array<int, 3> g{s.base[0] + i, s.base[1] + j, s.base[2] + k};
        const double p = common::dot(common::Vec3{double(g[0]), double(g[1]), double(g[2])} - x, n);
        if (p > best.distance) best = {g, p};
      }
  return best;
}

// Per vertex: viscous stress (6), pressure, found-fluid flag.
constexpr std::size_t kSlots = 8;

common::Vec3 stress_times(const double* s, const common::Vec3& a) {
  return {s[0] * a.x + s[3] * a.y + s[4] * a.z, s[3] * a.x + s[1] * a.y + s[5] * a.z,
          s[4] * a.x + s[5] * a.y + s[2] * a.z};
}

/// Area vectors of the surfaces parallel to the membrane: each vertex's area vector is exactly quadratic in a uniform
/// offset, so three offsets (0, 1, 2 lu) give it at any distance d. A neighbour's jump to another sample node then
/// leaves this vertex's area unchanged (a mesh through the actual sample points does not).
class ParallelSurfaces {
 public:
  explicit ParallelSurfaces(const SurfaceSample& surface) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::vector<double> uniform(surface.x_lu.size(), static_cast<double>(k));
      at_[k] = offset_area_vectors(surface.x_lu, surface.normal, uniform, surface.triangles);
    }
  }
  [[nodiscard]] common::Vec3 area(std::size_t v, double d) const {
    return 0.5 * (d - 1.0) * (d - 2.0) * at_[0][v] - d * (d - 2.0) * at_[1][v] + 0.5 * d * (d - 1.0) * at_[2][v];
  }

 private:
  std::array<std::vector<common::Vec3>, 3> at_;
};

/// The area vector each vertex's stress acts on.
std::vector<common::Vec3> acting_areas(const SurfaceSample& surface, const std::optional<ParallelSurfaces>& parallel,
                                       const std::vector<double>& distance, TractionArea rule) {
  std::vector<common::Vec3> area(surface.x_lu.size());
  if (rule == TractionArea::membrane) {
    for (std::size_t v = 0; v < area.size(); ++v) area[v] = surface.area_lu[v] * surface.normal[v];
    return area;
  }
  if (!parallel) throw std::invalid_argument("fluid_traction: the sampled surface needs triangles");
  for (std::size_t v = 0; v < area.size(); ++v) area[v] = parallel->area(v, distance[v]);
  if (rule == TractionArea::sampled_surface) return area;
  double sampled = 0.0;
  double own = 0.0;
  for (std::size_t v = 0; v < area.size(); ++v) {
    sampled += common::norm(area[v]);
    own += surface.area_lu[v];
  }
  const double factor = own > 0.0 ? sampled / own : 1.0;
  for (std::size_t v = 0; v < area.size(); ++v) area[v] = factor * surface.area_lu[v] * surface.normal[v];
  return area;
}

/// Per vertex: the cone from the centroid to its membrane area (these sum to the mesh volume exactly) plus the shell
/// out to its sample distance (Simpson's rule, exact for the quadratic parallel areas).
std::vector<double> enclosed_volumes(const SurfaceSample& surface, const ParallelSurfaces& parallel,
                                     const std::vector<double>& distance) {
  const std::size_t nv = surface.x_lu.size();
  common::Vec3 c;
  for (const auto& x : surface.x_lu) c += x / static_cast<double>(nv);
  std::vector<double> volume(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const double d = distance[v];
    const common::Vec3 own = parallel.area(v, 0.0);
    const double cone = common::dot(surface.x_lu[v] - c, own) / 3.0;
    const double shell =
        d / 6.0 * (common::norm(own) + 4.0 * common::norm(parallel.area(v, 0.5 * d)) + common::norm(parallel.area(v, d)));
    volume[v] = cone + shell;
  }
  return volume;
}

}  // namespace

TractionResult fluid_traction(const ImmersedBoundary& ibm, const FluidLattice& lattice, const SurfaceSample& surface,
                              const std::vector<std::vector<int>>& ring, TractionArea area_rule) {
  const std::size_t nv = surface.x_lu.size();
  if (surface.normal.size() != nv || surface.area_lu.size() != nv) throw std::invalid_argument("fluid_traction: sizes differ");
  std::vector<double> slots(kSlots * nv, 0.0);
  std::vector<double> distance(nv);   // the same on every rank: the stencil is a function of x alone
  std::array<int, 3> local{};
  for (std::size_t v = 0; v < nv; ++v) {
    const SampleNode sample = outermost_node(ibm.settings().kernel, surface.x_lu[v], surface.normal[v]);
    distance[v] = sample.distance;
    if (!ibm.to_local(sample.node, local) || !lattice.is_fluid(local[0], local[1], local[2])) continue;
    const SymTensor s = lattice.viscous_stress(local[0], local[1], local[2]);
    for (std::size_t a = 0; a < 6; ++a) slots[kSlots * v + a] = s[a];
    slots[kSlots * v + 6] = lattice.moments(local[0], local[1], local[2]).rho / 3.0;   // p = c_s^2 rho
    slots[kSlots * v + 7] = 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, slots.data(), static_cast<int>(slots.size()), MPI_DOUBLE, MPI_SUM,
                lattice.decomposition().comm());
  std::optional<ParallelSurfaces> parallel;   // needs the triangles; only the `membrane` rule goes without
  if (!surface.triangles.empty()) parallel.emplace(surface);
  const std::vector<common::Vec3> area = acting_areas(surface, parallel, distance, area_rule);
  TractionResult result;
  double pa = 0.0;
  double a_sum = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    result.mean_sample_distance_lu += distance[v] / static_cast<double>(nv);
    if (slots[kSlots * v + 7] == 0.0) continue;
    pa += slots[kSlots * v + 6] * common::norm(area[v]);
    a_sum += common::norm(area[v]);
  }
  result.mean_pressure_lu = a_sum > 0.0 ? pa / a_sum : 0.0;
  result.force_lu.assign(nv, {});
  for (std::size_t v = 0; v < nv; ++v) {
    if (slots[kSlots * v + 7] == 0.0) {
      ++result.vertices_without_fluid;
      continue;
    }
    const double dp = slots[kSlots * v + 6] - result.mean_pressure_lu;
    result.force_lu[v] = stress_times(&slots[kSlots * v], area[v]) - dp * area[v];
  }
  if (!ring.empty()) result.force_lu = median_filter(result.force_lu, ring);
  if (parallel) result.enclosed_volume_lu = enclosed_volumes(surface, *parallel, distance);
  result.sample_distance_lu = distance;
  return result;
}

}  // namespace hs::resolved
