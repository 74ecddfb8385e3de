// SPDX-License-Identifier: MIT
// The cytoplasm as the lattice's second fluid phase: the nodes inside a cell's membrane, kept up to date.
#include "resolved/ibm/cytoplasm_phase.hpp"

#include <stdexcept>
#include <vector>

#include "resolved/ibm/enclosed_nodes.hpp"

namespace hs::resolved {

CytoplasmPhase::CytoplasmPhase(FluidLattice& lattice, const common::Vec3& lattice_origin_m, double dx_m)
    : lattice_(lattice), origin_m_(lattice_origin_m), dx_m_(dx_m) {
  if (!lattice.two_phases()) throw std::invalid_argument("CytoplasmPhase: the lattice has no inner collision");
  if (!(dx_m > 0.0)) throw std::invalid_argument("CytoplasmPhase: dx must be > 0");
}

void CytoplasmPhase::update(std::span<const common::Vec3> x_m, std::span<const std::array<int, 3>> triangles) {
  std::vector<common::Vec3> x_lu(x_m.size());
  for (std::size_t v = 0; v < x_m.size(); ++v) x_lu[v] = (x_m[v] - origin_m_) / dx_m_;
  const auto& d = lattice_.decomposition();
  const auto inside = enclosed_nodes(x_lu, triangles, NodeBox{.nodes = d.global_nodes(), .periodic = d.periodic()});
  const auto offset = lattice_.offset();
  const auto& n = lattice_.layout().n;
  std::vector<std::ptrdiff_t> local;
  local.reserve(inside.size());
  for (const auto& g : inside) {
    std::array<int, 3> c{};
    bool mine = true;
    for (std::size_t a = 0; a < 3; ++a) {
      c[a] = g[a] - offset[a];
      mine = mine && c[a] >= 0 && c[a] < n[a];
    }
    if (mine) local.push_back(lattice_.layout().index(c[0], c[1], c[2]));
  }
  lattice_.set_inner_nodes(local);
}

}  // namespace hs::resolved
