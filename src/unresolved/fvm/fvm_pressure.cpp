// SPDX-License-Identifier: MIT
// FvmSolver: the PISO pressure equation (model A: Laplacian coefficient eps^2 / A) and velocity correction.
#include <algorithm>
#include <array>

#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

void FvmSolver::build_pressure_rows() {
  const auto& n = grid_.cells();
  p_row_ = BlockField<int>(n, -1);
  p_cell_.clear();
  bool outlet = false;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const long idx = static_cast<long>(p_row_.index(i, j, k));
        bool active = false;
        for (int a = 0; a < 3; ++a) {
          const auto& row = comp_[static_cast<std::size_t>(a)].row;
          const long st = row.stride(a);
          for (const long f : {idx, idx + st}) {
            if (row[static_cast<std::size_t>(f)] < 0) continue;
            active = true;
            // The face's place in the whole grid: a block's planes start at its first plane along z.
            const int offset = a == 2 ? grid_.first_plane() : 0;
            const int along = std::array<int, 3>{i, j, k}[static_cast<std::size_t>(a)] + (f == idx ? 0 : 1) + offset;
            const int last = grid_.global_cells()[static_cast<std::size_t>(a)];
            if (!grid_.periodic(a) && (along == 0 || along == last)) outlet = true;
          }
        }
        if (!active) continue;
        p_cell_.push_back(idx);
      }
    }
  }
  const int rows = static_cast<int>(p_cell_.size());
  p_first_row_ = rows_before(rows);
  for (int r = 0; r < rows; ++r) p_row_[static_cast<std::size_t>(p_cell_[static_cast<std::size_t>(r)])] = p_first_row_ + r;
  for (int a = 0; a < 3; ++a) fill_shared_ghosts(p_row_, a);
  // Without an outlet anywhere the pressure level is free: pin the first cell (OpenFOAM's pRefCell), global row 0.
  const bool any_outlet = max_over_ranks(outlet ? 1.0 : 0.0) > 0.0;
  const bool any_rows = sum_over_ranks(static_cast<double>(rows)) > 0.0;
  p_ref_row_ = (any_outlet || !any_rows) ? -1 : 0;
  p_rhs_.assign(p_cell_.size(), 0.0);
  p_x_.assign(p_cell_.size(), 0.0);
}

/// The momentum diagonal A of every velocity node, the neighbouring blocks' in the ghost planes: a pressure row
/// reads it on all six faces of its cell, and a block's top face belongs to the block above.
void FvmSolver::spread_momentum_diagonal() {
  for (int c = 0; c < 3; ++c) {
    const Component& comp = comp_[static_cast<std::size_t>(c)];
    BlockField<double>& a_face = a_face_[static_cast<std::size_t>(c)];
    if (a_face.data().empty()) a_face = BlockField<double>(grid_.cells(), 1.0);
    for (std::size_t r = 0; r < comp.node.size(); ++r) a_face[static_cast<std::size_t>(comp.node[r])] = comp.a[static_cast<long>(r)];
    for (int a = 0; a < 3; ++a) fill_shared_ghosts(a_face, a);
  }
}

void FvmSolver::build_pressure_matrix() {
  const int rows = static_cast<int>(p_cell_.size());
  // Rebuilt every step the coefficients change, into the same buffers: at 1e6 cells the pattern and values are ~100 MB,
  // which fresh vectors took from the kernel as new pages (zeroed on first touch) every step.
  CsrMatrix& a = p_matrix_;
  a.rows = rows;
  a.first_row = p_first_row_;
  a.row_ptr.assign(static_cast<std::size_t>(rows) + 1, 0);
  a.cols.clear();
  a.values.clear();
  const double inv_h2 = 1.0 / (h_ * h_);
  // At most 7 distinct entries per row (a periodic axis of 1 or 2 cells merges neighbours).
  struct Entry {
    int col;
    double value;
  };
  std::array<Entry, 7> entries{};
  int count = 0;
  auto add = [&](int col, double v) {
    for (int q = 0; q < count; ++q) {
      if (entries[static_cast<std::size_t>(q)].col == col) {
        entries[static_cast<std::size_t>(q)].value += v;
        return;
      }
    }
    entries[static_cast<std::size_t>(count++)] = {col, v};
  };
  a.cols.reserve(static_cast<std::size_t>(rows) * 7);
  a.values.reserve(static_cast<std::size_t>(rows) * 7);
  spread_momentum_diagonal();
  for (int r = 0; r < rows; ++r) {
    count = 0;
    const int self = p_first_row_ + r;
    add(self, self == p_ref_row_ ? 1.0 : 0.0);
    const long idx = p_cell_[static_cast<std::size_t>(r)];
    for (int ax = 0; ax < 3 && self != p_ref_row_; ++ax) {
      const Component& comp = comp_[static_cast<std::size_t>(ax)];
      const auto& ap = grid_.apertures(ax);
      const auto& a_face = a_face_[static_cast<std::size_t>(ax)];
      const long st = p_row_.stride(ax);
      for (const int s : {-1, 1}) {
        const long f = s < 0 ? idx : idx + st;
        if (comp.row[static_cast<std::size_t>(f)] < 0) continue;
        const double e = face_average(eps_, ax, f);
        const double d = e * e * ap[static_cast<std::size_t>(f)] / a_face[static_cast<std::size_t>(f)] * inv_h2;
        const int nrow = p_row_[static_cast<std::size_t>(idx + s * st)];
        if (nrow == self) continue;                // a one-cell periodic axis couples a cell to itself
        if (nrow < 0) {
          add(self, 2.0 * d);                      // outlet face: p = 0 half a cell away
          continue;
        }
        add(self, d);
        if (nrow != p_ref_row_) add(nrow, -d);
      }
    }
    // Emit in column order (selection over at most 7 entries).
    int last = -1;
    for (int emitted = 0; emitted < count; ++emitted) {
      int best = -1;
      for (int q = 0; q < count; ++q) {
        const int col = entries[static_cast<std::size_t>(q)].col;
        if (col > last && (best < 0 || col < entries[static_cast<std::size_t>(best)].col)) best = q;
      }
      last = entries[static_cast<std::size_t>(best)].col;
      a.cols.push_back(last);
      a.values.push_back(entries[static_cast<std::size_t>(best)].value);
    }
    a.row_ptr[static_cast<std::size_t>(r) + 1] = static_cast<int>(a.cols.size());
  }
  pressure_.set_matrix(a);
  if (!outlet_faces_.empty()) add_outlet_pressures();
}

void FvmSolver::fill_pressure_ghosts() {
  const auto& n = grid_.cells();
  for (int a = 0; a < 3; ++a) {
    if (!grid_.periodic(a)) {
      p_.fill_zero_gradient(a);
      const int na = n[static_cast<std::size_t>(a)];
      for (int hi = 0; hi < 2; ++hi) {
        if (grid_.side(a, hi).type != SideType::pressure_outlet) continue;
        // p = 0 on the outlet face: the ghost mirrors the first cell with opposite sign.
        p_.for_each_in_plane(a, hi == 1 ? na : -1, [&](std::size_t idx) { p_[idx] = -p_[idx]; });
      }
    }
    fill_shared_ghosts(p_, a);
  }
  // Openings' pressure outlets: p = p_b on the face, so the ghost cell mirrors the first cell about p_b.
  for (const OutletFace& f : outlet_faces_) {
    p_[static_cast<std::size_t>(f.ghost)] = 2.0 * f.p_kin - p_[static_cast<std::size_t>(f.interior)];
  }
}

void FvmSolver::pressure_corrector(bool final) {
  for (int c = 0; c < 3; ++c) {
    Component& comp = comp_[static_cast<std::size_t>(c)];
    if (comp.node.empty()) continue;
    Eigen::VectorXd mx(comp.x.size());
    comp.solver->multiply({comp.x.data(), static_cast<std::size_t>(comp.x.size())}, {mx.data(), static_cast<std::size_t>(mx.size())});   // hypre's product: it fetches the neighbouring ranks' unknowns
    comp.hbya = (comp.b + comp.a.cwiseProduct(comp.x) - mx).cwiseQuotient(comp.a);
    scatter(c, comp.hbya, hb_[static_cast<std::size_t>(c)]);
  }
  const long rows = static_cast<long>(p_cell_.size());
  const double inv_h = 1.0 / h_;
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
  for (long r = 0; r < rows; ++r) {
    const long idx = p_cell_[static_cast<std::size_t>(r)];
    double div = 0.0;
    for (int ax = 0; ax < 3; ++ax) {
      const auto& hb = hb_[static_cast<std::size_t>(ax)];
      const auto& ap = grid_.apertures(ax);
      const long hi = idx + hb.stride(ax);
      div += face_average(eps_, ax, hi) * ap[static_cast<std::size_t>(hi)] * hb[static_cast<std::size_t>(hi)] -
             face_average(eps_, ax, idx) * ap[static_cast<std::size_t>(idx)] * hb[static_cast<std::size_t>(idx)];
    }
    p_rhs_[static_cast<std::size_t>(r)] = p_first_row_ + r == p_ref_row_ ? 0.0 : -div * inv_h - deps_dt_[static_cast<std::size_t>(idx)];
    if (!p_bc_.empty()) p_rhs_[static_cast<std::size_t>(r)] += p_bc_[static_cast<std::size_t>(r)];
    p_x_[static_cast<std::size_t>(r)] = p_[static_cast<std::size_t>(idx)];
  }
  SolveTolerance tol = piso_.pressure;
  if (final) tol.rel_tol = 0.0;
  stats_.pressure_iterations += pressure_.solve(p_rhs_, p_x_, tol);
  for (long r = 0; r < rows; ++r) p_[static_cast<std::size_t>(p_cell_[static_cast<std::size_t>(r)])] = p_x_[static_cast<std::size_t>(r)];
  fill_pressure_ghosts();
  for (int c = 0; c < 3; ++c) {
    Component& comp = comp_[static_cast<std::size_t>(c)];
    const long n = static_cast<long>(comp.node.size());
    const long sc = p_.stride(c);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (long r = 0; r < n; ++r) {
      const long idx = comp.node[static_cast<std::size_t>(r)];
      const double grad_p = (p_[static_cast<std::size_t>(idx)] - p_[static_cast<std::size_t>(idx - sc)]) * inv_h;
      comp.x[r] = comp.hbya[r] - face_average(eps_, c, idx) * grad_p / comp.a[r];
    }
  }
}

}  // namespace hs::unresolved
