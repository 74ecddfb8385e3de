// SPDX-License-Identifier: MIT
// FvmSolver: the pressure outlets of named openings (pressure on the face, open tangential ghosts) and the flux
// through each opening.
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

using hs::common::OpeningFlowType;
using hs::common::Vec3;

void FvmSolver::build_opening_boundaries() {
  const auto& openings = grid_.openings();
  int outlets = 0;
  double level_Pa = 0.0;
  for (const auto& oc : openings) {
    if (oc.type != OpeningFlowType::pressure_outlet) continue;
    level_Pa += oc.pressure_Pa;
    ++outlets;
  }
  if (outlets > 0) p_level_kin_ = level_Pa / outlets / fluid_.density_kg_m3;
  for (std::size_t k = 0; k < openings.size(); ++k) {
    if (openings[k].type != OpeningFlowType::pressure_outlet) continue;
    const OpeningNodes& on = grid_.opening_nodes(k);
    const long st = p_.stride(on.axis);
    const double p_kin = openings[k].pressure_Pa / fluid_.density_kg_m3 - p_level_kin_;
    for (const std::size_t node : on.nodes) {
      const long idx = static_cast<long>(node);
      // Face node index i along the axis sits between cells i - 1 and i: the low side's first cell is i = 0.
      outlet_faces_.push_back(on.high == 1 ? OutletFace{on.axis, idx, idx - st, idx, p_kin}
                                           : OutletFace{on.axis, idx, idx, idx - st, p_kin});
    }
  }
  // Tangential components beyond a side, where a pressure outlet's disc holds the point of the face next to them.
  const auto& n = grid_.cells();
  for (int c = 0; c < 3; ++c) {
    for (int a = 0; a < 3; ++a) {
      if (a == c || grid_.periodic(a)) continue;
      const int b = 3 - a - c;
      const long st = u_[static_cast<std::size_t>(c)].stride(a);
      for (int high = 0; high < 2; ++high) {
        const int along = high == 1 ? n[static_cast<std::size_t>(a)] : -1;
        for (int q = 0; q < grid_.node_count(c, c); ++q) {
          for (int r = 0; r < grid_.node_count(c, b); ++r) {
            std::array<int, 3> ijk{};
            ijk[static_cast<std::size_t>(a)] = along;
            ijk[static_cast<std::size_t>(c)] = q;
            ijk[static_cast<std::size_t>(b)] = r;
            Vec3 x = grid_.node_position_m(c, ijk[0], ijk[1], ijk[2]);
            x[a] = high == 1 ? grid_.origin_m()[a] + n[static_cast<std::size_t>(a)] * h_ : grid_.origin_m()[a];
            const auto* open = grid_.opening_at(a, high, x);
            if (open == nullptr || open->type != OpeningFlowType::pressure_outlet) continue;
            const std::size_t ghost = u_[static_cast<std::size_t>(c)].index(ijk[0], ijk[1], ijk[2]);
            const std::size_t interior =
                high == 1 ? ghost - static_cast<std::size_t>(st) : ghost + static_cast<std::size_t>(st);
            open_ghosts_[static_cast<std::size_t>(c)].push_back({a, high, ghost, interior});
          }
        }
      }
    }
  }
}

/// The source of the Dirichlet pressure on an outlet face: the matrix holds 2 d (p_P - p_b) for it (the ghost cell
/// mirrors p_P about p_b half a cell away), the diagonal part 2 d p_P is in the matrix, 2 d p_b goes to the right side.
void FvmSolver::add_outlet_pressures() {
  p_bc_.assign(p_cell_.size(), 0.0);
  const double inv_h2 = 1.0 / (h_ * h_);
  for (const OutletFace& f : outlet_faces_) {
    const int row = p_row_[static_cast<std::size_t>(f.interior)];
    const Component& comp = comp_[static_cast<std::size_t>(f.axis)];
    if (row < 0 || comp.row[static_cast<std::size_t>(f.node)] < 0) continue;
    const double e = face_average(eps_, f.axis, f.node);
    const double a = a_face_[static_cast<std::size_t>(f.axis)][static_cast<std::size_t>(f.node)];
    const double d = e * e * grid_.apertures(f.axis)[static_cast<std::size_t>(f.node)] / a * inv_h2;
    p_bc_[static_cast<std::size_t>(row - p_first_row_)] += 2.0 * d * f.p_kin;
  }
}

double FvmSolver::opening_flow_rate_m3_s(std::size_t k) const {
  const OpeningNodes& on = grid_.opening_nodes(k);
  const auto& phi = phi_[static_cast<std::size_t>(on.axis)];
  double sum = 0.0;
  for (const std::size_t idx : on.nodes) sum += phi[idx];
  return sum_over_ranks(sum) * grid_.openings()[k].opening.normal[on.axis];
}

}  // namespace hs::unresolved
