// SPDX-License-Identifier: MIT
// Many membranes in one lattice fluid: one CoupledCell (own npFEM solve) per cell, one forcing pass over all their
// markers, and the cell-cell contact repulsion between them (issue #24, item 1).
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "common/units/unit_converter.hpp"
#include "common/vec3.hpp"
#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/ibm/immersed_boundary.hpp"
#include "resolved/membrane/cell_contact.hpp"
#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

/// Forces a case adds to one cell's membrane before its step (e.g. the walls): (cell index, vertex positions in SI,
/// unwrapped; forces in newtons to add to).
using CellForces = std::function<void(int, std::span<const common::Vec3>, std::vector<common::Vec3>&)>;

/// The stages of CoupledCell for N cells sharing one lattice (resolved-methods.md 2.3):
///  1. membrane_solve: at the start of a membrane interval the contact forces of every cell are computed from the
///     positions of all cells at time t (add_cell_contact_forces: equal and opposite), then each cell takes its
///     fluid force + contact + the case's forces and steps its own npFEM solve.
///  2. ibm_forcing: ONE multi-direct forcing pass over the markers of all cells (ImmersedBoundary::apply clears the
///     force field first, so a pass per cell would erase the others'); each cell takes its slice of the markers' forces.
///  3. lbm_step once; 4. markers_advect per cell.
/// With one cell every stage does exactly what CoupledCell::step does (the same numbers, bit for bit: tested).
/// Every rank holds every membrane, as CoupledCell does; the contact search runs on replicated data.
class CellSuspension {
 public:
  /// `coupling` applies to every cell (its add_forces_N is ignored: give `case_forces`); `contact.range_m == 0`: no
  /// contact repulsion.
  CellSuspension(FluidLattice& lattice, const common::UnitConverter& units, const CouplingSettings& coupling,
                 const CellContactSpec& contact, CellForces case_forces = {});
  CellSuspension(const CellSuspension&) = delete;
  CellSuspension& operator=(const CellSuspension&) = delete;

  /// Adds a cell whose membrane is already where it belongs (its step must be membrane_every * dt).
  void add_cell(std::unique_ptr<NpfemSolver> membrane);

  void membrane_solve();
  void ibm_forcing();
  void lbm_step();
  void markers_advect();
  void step();

  [[nodiscard]] int size() const { return static_cast<int>(cells_.size()); }
  [[nodiscard]] NpfemSolver& membrane(int i) { return *membranes_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] const NpfemSolver& membrane(int i) const { return *membranes_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] CoupledCell& cell(int i) { return *cells_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] const CoupledCell& cell(int i) const { return *cells_[static_cast<std::size_t>(i)]; }
  /// The contact search of the last membrane step (pairs, closest inter-cell vertex distance within range).
  [[nodiscard]] const CellContactReport& contact_report() const { return contact_report_; }
  /// The contact forces of the last membrane step, per cell and vertex (newtons).
  [[nodiscard]] const std::vector<std::vector<common::Vec3>>& contact_forces_N() const { return contact_N_; }
  [[nodiscard]] bool interval_starts() const { return cells_.empty() || cells_.front()->interval_starts(); }

 private:
  void compute_contact();

  FluidLattice& lattice_;
  const common::UnitConverter& units_;
  CouplingSettings coupling_;
  CellContactSpec contact_;
  CellForces case_forces_;
  ImmersedBoundary ibm_;   // the one forcing pass over all markers
  std::vector<std::unique_ptr<NpfemSolver>> membranes_;
  std::vector<std::unique_ptr<CoupledCell>> cells_;
  std::vector<std::vector<common::Vec3>> contact_N_;
  CellContactReport contact_report_;
  Markers all_;   // concatenated markers of the current forcing pass
};

}  // namespace hs::resolved
