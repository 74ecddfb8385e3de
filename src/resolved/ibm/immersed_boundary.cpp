// SPDX-License-Identifier: MIT
// Immersed boundary coupling on the lattice: interpolation to markers, spreading of marker forces, multi-direct forcing.
#include "resolved/ibm/immersed_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <mpi.h>

namespace hs::resolved {

ImmersedBoundary::ImmersedBoundary(FluidLattice& lattice, const IbmSettings& settings)
    : lattice_(lattice), settings_(settings) {
  if (settings_.iterations < 1) throw std::invalid_argument("IBM iterations must be >= 1");
  if (lattice_.force_field().empty()) lattice_.enable_force_field();
}

bool ImmersedBoundary::to_local(std::array<int, 3> global, std::array<int, 3>& local) const {
  const auto& decomposition = lattice_.decomposition();
  const auto& n_global = decomposition.global_nodes();
  const auto& periodic = decomposition.periodic();
  const auto offset = lattice_.offset();
  const auto& n_local = lattice_.layout().n;
  for (int a = 0; a < 3; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    int g = global[ua];
    if (periodic[ua]) {
      g %= n_global[ua];
      if (g < 0) g += n_global[ua];
    } else if (g < 0 || g >= n_global[ua]) {
      return false;
    }
    const int l = g - offset[ua];
    if (l < 0 || l >= n_local[ua]) return false;
    local[ua] = l;
  }
  return true;
}

namespace {

/// Adds the per-rank partial sums (rho, j_x, j_y, j_z per marker) over all ranks and turns them into the
/// marker density and velocity u = j / rho: each rank holds only its own nodes' share of every stencil.
MarkerFluid reduce_marker_sums(std::vector<double>& sums, MPI_Comm comm) {
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, comm);
  const std::size_t n = sums.size() / 4;
  MarkerFluid out;
  out.rho_lu.resize(n);
  out.u_lu.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (sums[4 * k] <= 0.0) {   // a marker inside a wall, no fluid node in reach: the wall, at rest
      out.rho_lu[k] = 1.0;
      continue;
    }
    out.rho_lu[k] = sums[4 * k];
    out.u_lu[k] = common::Vec3{sums[4 * k + 1], sums[4 * k + 2], sums[4 * k + 3]} / sums[4 * k];
  }
  return out;
}

/// Per marker: 1 if its fluid nodes carry the whole weight (the kernels sum to one to ~1e-16; 1e-12 tells a wall
/// or a face beyond the box apart from round-off), else 1 / that weight, or 0 without any fluid node.
std::vector<double> cut_stencil_scale_from(std::vector<double>& fluid_weight, MPI_Comm comm) {
  MPI_Allreduce(MPI_IN_PLACE, fluid_weight.data(), static_cast<int>(fluid_weight.size()), MPI_DOUBLE, MPI_SUM, comm);
  std::vector<double> scale(fluid_weight.size(), 1.0);
  for (std::size_t k = 0; k < fluid_weight.size(); ++k) {
    if (fluid_weight[k] < 1.0 - 1e-12) scale[k] = fluid_weight[k] > 0.0 ? 1.0 / fluid_weight[k] : 0.0;
  }
  return scale;
}

}  // namespace

void ImmersedBoundary::for_each_local_node(const common::Vec3& x_lu,
                                           const std::function<void(int, int, int, double)>& visit) const {
  const DeltaStencil s = delta_stencil(settings_.kernel, x_lu);
  std::array<int, 3> local{};
  for (int k = 0; k < s.points; ++k) {
    for (int j = 0; j < s.points; ++j) {
      for (int i = 0; i < s.points; ++i) {
        if (!to_local({s.base[0] + i, s.base[1] + j, s.base[2] + k}, local)) continue;
        visit(local[0], local[1], local[2], s.w(i, j, k));
      }
    }
  }
}

std::vector<double> ImmersedBoundary::cut_stencil_scale(std::span<const common::Vec3> x_lu) const {
  const std::size_t n = x_lu.size();
  std::vector<double> fluid_weight(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for_each_local_node(x_lu[k], [&](int x, int y, int z, double w) {
      if (lattice_.is_fluid(x, y, z)) fluid_weight[k] += w;
    });
  }
  return cut_stencil_scale_from(fluid_weight, lattice_.decomposition().comm());
}

MarkerFluid ImmersedBoundary::interpolate(std::span<const common::Vec3> x_lu) const {
  const std::size_t n = x_lu.size();
  const std::vector<double> scale = cut_stencil_scale(x_lu);
  std::vector<double> sums(4 * n, 0.0);   // rho, j_x, j_y, j_z per marker
  for (std::size_t k = 0; k < n; ++k) {
    for_each_local_node(x_lu[k], [&](int x, int y, int z, double w) {
      if (!lattice_.is_fluid(x, y, z)) return;
      const NodeMoments m = lattice_.moments(x, y, z);
      const double ws = w * scale[k];
      sums[4 * k] += ws * m.rho;
      for (int a = 0; a < 3; ++a) sums[4 * k + 1 + static_cast<std::size_t>(a)] += ws * m.rho * m.u[a];
    });
  }
  return reduce_marker_sums(sums, lattice_.decomposition().comm());
}

void ImmersedBoundary::spread(std::span<const common::Vec3> x_lu, std::span<const common::Vec3> f_lu) {
  if (x_lu.size() != f_lu.size()) throw std::invalid_argument("spread: one force per marker");
  forced_nodes_known_ = false;   // these forces are not tracked: the next apply() clears the whole field
  const std::vector<double> scale = cut_stencil_scale(x_lu);
  for (std::size_t k = 0; k < x_lu.size(); ++k) {
    for_each_local_node(x_lu[k], [&](int x, int y, int z, double w) {
      if (lattice_.is_fluid(x, y, z)) lattice_.add_force(x, y, z, (w * scale[k]) * f_lu[k]);
    });
  }
}

namespace {

double max_slip(const Markers& markers, const MarkerFluid& fluid) {
  double slip = 0.0;
  for (std::size_t k = 0; k < markers.x_lu.size(); ++k) slip = std::max(slip, common::norm(markers.u_lu[k] - fluid.u_lu[k]));
  return slip;
}

}  // namespace

namespace {

/// One (marker, local node) pair of the stencils: the node's force-field index, the weight (0 for a wall node,
/// renormalised over the fluid nodes of a cut stencil), and the node's rho and momentum without any IBM force.
struct StencilEntry {
  std::size_t node;
  double weight;
  double rho;
  common::Vec3 j0;
  bool fluid;
};

std::vector<StencilEntry> gather_stencils(const ImmersedBoundary& ibm, const FluidLattice& lattice,
                                         std::span<const common::Vec3> x_lu, std::vector<std::size_t>& first,
                                         std::vector<std::int32_t>& node_slot, std::vector<std::size_t>& touched,
                                         std::vector<double>& scale) {
  const std::size_t n = x_lu.size();
  std::vector<StencilEntry> entries;
  first.assign(n + 1, 0);
  const auto& layout = lattice.layout();
  node_slot.resize(layout.volume(), -1);
  // The stencils of markers ~1 lu apart overlap several times over; reading a node's 19 populations is a scatter
  // through memory (AA layout), so each node is read once and its entry copied (the same numbers, bit for bit).
  touched.clear();
  for (std::size_t k = 0; k < n; ++k) {
    first[k] = entries.size();
    ibm.for_each_local_node(x_lu[k], [&](int x, int y, int z, double w) {
      const auto node = static_cast<std::size_t>(layout.index(x, y, z));
      if (node_slot[node] >= 0) {
        StencilEntry e = entries[static_cast<std::size_t>(node_slot[node])];
        e.weight = w;
        entries.push_back(e);
        return;
      }
      node_slot[node] = static_cast<std::int32_t>(entries.size());
      touched.push_back(node);
      if (!lattice.is_fluid(x, y, z)) {
        entries.push_back({node, w, 0.0, {}, false});
        return;
      }
      const NodeMoments m = lattice.moments(x, y, z);
      entries.push_back({node, w, m.rho, m.rho * m.u, true});
    });
  }
  for (const std::size_t node : touched) node_slot[node] = -1;
  first[n] = entries.size();
  // Cut stencils (see the class comment): renormalise over the fluid nodes of every rank.
  std::vector<double> fluid_weight(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t e = first[k]; e < first[k + 1]; ++e) fluid_weight[k] += entries[e].fluid ? entries[e].weight : 0.0;
  }
  scale = cut_stencil_scale_from(fluid_weight, lattice.decomposition().comm());
  for (std::size_t k = 0; k < n; ++k) {
    if (scale[k] == 1.0) continue;
    for (std::size_t e = first[k]; e < first[k + 1]; ++e) entries[e].weight = entries[e].fluid ? entries[e].weight * scale[k] : 0.0;
  }
  return entries;
}

}  // namespace

ForcingReport ImmersedBoundary::apply(const Markers& markers) {
  const std::size_t n = markers.x_lu.size();
  if (markers.u_lu.size() != n || markers.area_lu.size() != n) throw std::invalid_argument("IBM markers: sizes differ");
  if (forced_nodes_known_) {
    const std::span<double> old = lattice_.force_field();
    const std::size_t volume = lattice_.layout().volume();
    for (const std::size_t node : forced_nodes_) old[node] = old[volume + node] = old[2 * volume + node] = 0.0;
  } else {
    lattice_.clear_force_field();
  }
  // The populations do not change during the iterations, only the force field: rho and j0 = sum f c + F_body/2 are
  // read once, and the half-force momentum of a node is j0 + F_ibm/2 (the same numbers moments() would give).
  std::vector<std::size_t> first;
  std::vector<double> scale;   // per marker, global: 0 when no rank holds a fluid node of its stencil
  const std::vector<StencilEntry> entries =
      gather_stencils(*this, lattice_, markers.x_lu, first, node_slot_, forced_nodes_, scale);
  forced_nodes_known_ = true;   // every node this apply() writes is in forced_nodes_ (wall nodes there get nothing)
  const auto& layout = lattice_.layout();
  const std::span<double> field = lattice_.force_field();
  const std::size_t stride = layout.volume();
  std::vector<double> sums(4 * n);
  auto interpolate_cached = [&]() {
    std::fill(sums.begin(), sums.end(), 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
        const StencilEntry& s = entries[e];
        sums[4 * k] += s.weight * s.rho;
        if (!s.fluid) continue;
        for (std::size_t a = 0; a < 3; ++a) sums[4 * k + 1 + a] += s.weight * (s.j0[static_cast<int>(a)] + 0.5 * field[a * stride + s.node]);
      }
    }
    return reduce_marker_sums(sums, lattice_.decomposition().comm());
  };
  ForcingReport report;
  report.marker_force_lu.assign(n, {});
  MarkerFluid fluid = interpolate_cached();
  report.slip_before_lu = max_slip(markers, fluid);
  for (int it = 0; it < settings_.iterations; ++it) {
    for (std::size_t k = 0; k < n; ++k) {
      // Guo forcing: the half-force velocity moves by F/(2 rho), hence the factor 2 (Kang & Hassan 2011).
      const common::Vec3 df = 2.0 * markers.area_lu[k] * fluid.rho_lu[k] * (markers.u_lu[k] - fluid.u_lu[k]);
      report.total_force_lu += df;
      if (scale[k] > 0.0) report.marker_force_lu[k] += df;
      for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
        const StencilEntry& s = entries[e];
        if (!s.fluid) continue;
        for (std::size_t a = 0; a < 3; ++a) field[a * stride + s.node] += s.weight * df[static_cast<int>(a)];
      }
    }
    if (it + 1 < settings_.iterations || settings_.measure_slip) fluid = interpolate_cached();
  }
  if (settings_.measure_slip) report.slip_after_lu = max_slip(markers, fluid);
  return report;
}

}  // namespace hs::resolved
