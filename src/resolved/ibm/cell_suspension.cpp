// SPDX-License-Identifier: MIT
// Many membranes in one lattice fluid: per-cell npFEM solves, one forcing pass, cell-cell contact.
#include "resolved/ibm/cell_suspension.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hs::resolved {

using common::Vec3;

CellSuspension::CellSuspension(FluidLattice& lattice, const common::UnitConverter& units,
                               const CouplingSettings& coupling, const CellContactSpec& contact, CellForces case_forces)
    : lattice_(lattice), units_(units), coupling_(coupling), contact_(contact), case_forces_(std::move(case_forces)),
      ibm_(lattice, coupling.ibm) {
  coupling_.add_forces_N = {};
}

void CellSuspension::add_cell(std::unique_ptr<NpfemSolver> membrane) {
  if (!cells_.empty() && cells_.front()->steps() != 0) throw std::logic_error("add cells before the first step");
  const int index = size();
  CouplingSettings s = coupling_;
  // The cell's extra forces: the case's (walls), then its share of the contact forces computed for all cells at the
  // start of this membrane step (compute_contact), so every cell sees the others at the same time t.
  s.add_forces_N = [this, index](std::span<const Vec3> x_m, std::vector<Vec3>& f_N) {
    if (case_forces_) case_forces_(index, x_m, f_N);
    const auto& c = contact_N_[static_cast<std::size_t>(index)];
    for (std::size_t v = 0; v < c.size() && v < f_N.size(); ++v) f_N[v] += c[v];
  };
  membranes_.push_back(std::move(membrane));
  cells_.push_back(std::make_unique<CoupledCell>(lattice_, *membranes_.back(), units_, s));
  contact_N_.emplace_back(static_cast<std::size_t>(membranes_.back()->vertex_count()));
}

void CellSuspension::compute_contact() {
  for (auto& f : contact_N_) std::fill(f.begin(), f.end(), Vec3{});
  contact_report_ = {};
  if (contact_.range_m <= 0.0 || cells_.size() < 2) return;
  std::vector<std::vector<Vec3>> x(membranes_.size());
  std::vector<std::span<const Vec3>> spans;
  for (std::size_t c = 0; c < membranes_.size(); ++c) {
    x[c] = membranes_[c]->positions_m();
    spans.emplace_back(x[c]);
  }
  contact_report_ = add_cell_contact_forces(spans, contact_N_, contact_);
}

void CellSuspension::membrane_solve() {
  if (interval_starts()) compute_contact();
  for (auto& c : cells_) c->membrane_solve();
}

void CellSuspension::ibm_forcing() {
  if (cells_.empty()) return;
  all_.x_lu.clear();
  all_.u_lu.clear();
  all_.area_lu.clear();
  for (const auto& c : cells_) {
    const Markers& m = c->markers();
    all_.x_lu.insert(all_.x_lu.end(), m.x_lu.begin(), m.x_lu.end());
    all_.u_lu.insert(all_.u_lu.end(), m.u_lu.begin(), m.u_lu.end());
    all_.area_lu.insert(all_.area_lu.end(), m.area_lu.begin(), m.area_lu.end());
  }
  ForcingReport all = ibm_.apply(all_);
  if (cells_.size() == 1) {
    cells_.front()->take_forcing(std::move(all));
    return;
  }
  // Each cell's slice of the per-marker forces; its total is the sum of its markers' (markers without any fluid
  // node in reach spread nothing and count nothing), the slips are the pass's (all markers).
  std::size_t first = 0;
  for (auto& c : cells_) {
    const std::size_t n = c->markers().x_lu.size();
    ForcingReport part;
    part.slip_before_lu = all.slip_before_lu;
    part.slip_after_lu = all.slip_after_lu;
    part.marker_force_lu.assign(all.marker_force_lu.begin() + static_cast<std::ptrdiff_t>(first),
                                all.marker_force_lu.begin() + static_cast<std::ptrdiff_t>(first + n));
    for (const Vec3& f : part.marker_force_lu) part.total_force_lu += f;
    c->take_forcing(std::move(part));
    first += n;
  }
}

void CellSuspension::lbm_step() { lattice_.step(); }

void CellSuspension::markers_advect() {
  for (auto& c : cells_) c->markers_advect();
}

void CellSuspension::step() {
  membrane_solve();
  ibm_forcing();
  lbm_step();
  markers_advect();
}

}  // namespace hs::resolved
