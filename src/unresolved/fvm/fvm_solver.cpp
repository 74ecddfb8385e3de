// SPDX-License-Identifier: MIT
// FvmSolver: set-up of the unknowns, the PISO time step, flow-rate control and checks.
#include "unresolved/fvm/fvm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {

using hs::common::Vec3;

PressureCoupling pressure_coupling_from_name(std::string_view name) {
  if (name == "piso") return PressureCoupling::piso;
  if (name == "projection") return PressureCoupling::projection;
  throw hs::common::ConfigError(fmt::format("unknown pressure coupling '{}': use \"projection\" or \"piso\"", name));
}

FvmSolver::FvmSolver(const FvmGrid& grid, const FluidProperties& fluid, const PisoSettings& piso, const FlowDrive& drive,
                     MPI_Comm comm)
    : grid_(grid), comm_(comm), fluid_(fluid), piso_(piso), drive_(drive), h_(grid.dx_m()), pressure_(comm) {
  if (!(fluid.density_kg_m3 > 0.0) || !(fluid.kinematic_viscosity_m2_s > 0.0)) {
    throw hs::common::ConfigError(fmt::format("FVM: density ({} kg/m^3) and kinematic viscosity ({} m^2/s) must be > 0",
                                              fluid.density_kg_m3, fluid.kinematic_viscosity_m2_s));
  }
  if (!(piso.dt_s > 0.0) || piso.correctors < 1 || !(piso.max_courant > 0.0)) {
    throw hs::common::ConfigError(fmt::format("FVM: dt_s = {} must be > 0, correctors = {} >= 1, max_courant = {} > 0",
                                              piso.dt_s, piso.correctors, piso.max_courant));
  }
  if (piso.coupling == PressureCoupling::projection && !piso.momentum_predictor) {
    throw hs::common::ConfigError("FVM: the projection needs the momentum predictor (its u* is what is projected)");
  }
  if (drive.mode != FlowDrive::Mode::none && !grid.periodic(drive.axis)) {
    throw hs::common::ConfigError(fmt::format("FVM: the flow drive needs a periodic axis; axis {} is not periodic",
                                              "xyz"[drive.axis]));
  }
  if (drive.mode == FlowDrive::Mode::pressure_gradient) drive_gradient_ = drive.pressure_gradient_Pa_m / fluid.density_kg_m3;
  const auto& n = grid.cells();
  eps_ = BlockField<double>(n, 1.0);
  ksl_ = BlockField<double>(n, 0.0);
  deps_dt_ = BlockField<double>(n, 0.0);
  visc_ = BlockField<double>(n, 1.0);
  us_ = BlockField<Vec3>(n, Vec3{});
  force_ = BlockField<Vec3>(n, Vec3{});
  p_ = BlockField<double>(n, 0.0);
  for (int c = 0; c < 3; ++c) {
    u_[static_cast<std::size_t>(c)] = grid.fixed_values(c);
    viscous_force_[static_cast<std::size_t>(c)] = grid.fixed_values(c);   // the face field's shape; 0 off the unknowns
    for (double& v : viscous_force_[static_cast<std::size_t>(c)].data()) v = 0.0;
    hb_[static_cast<std::size_t>(c)] = grid.fixed_values(c);
    phi_[static_cast<std::size_t>(c)] = BlockField<double>(n, 0.0);
    build_component(c);
  }
  build_pressure_rows();
  if (!grid.openings().empty()) build_opening_boundaries();
  update_fluxes();
  update_viscous_force();
}

void FvmSolver::build_component(int c) {
  Component& comp = comp_[static_cast<std::size_t>(c)];
  const auto& kinds = grid_.kinds(c);
  comp.row = BlockField<int>(grid_.cells(), -1);
  for (int k = 0; k < grid_.node_count(c, 2); ++k) {
    for (int j = 0; j < grid_.node_count(c, 1); ++j) {
      for (int i = 0; i < grid_.node_count(c, 0); ++i) {
        if (kinds(i, j, k) != static_cast<std::uint8_t>(NodeKind::active)) continue;
        comp.node.push_back(static_cast<long>(comp.row.index(i, j, k)));
      }
    }
  }
  const int rows = static_cast<int>(comp.node.size());
  comp.link_id.assign(static_cast<std::size_t>(rows), -1);
  // This rank's rows come after the lower ranks' (hypre's layout); comp.row holds global row numbers, the
  // neighbouring blocks' in the ghost planes.
  const int first_row = rows_before(rows);
  for (int r = 0; r < rows; ++r) comp.row[static_cast<std::size_t>(comp.node[static_cast<std::size_t>(r)])] = first_row + r;
  for (int a = 0; a < 3; ++a) fill_shared_ghosts(comp.row, a);
  CsrMatrix m{.rows = rows, .first_row = first_row, .row_ptr = {0}, .cols = {}, .values = {}};
  m.cols.reserve(static_cast<std::size_t>(rows) * 7);
  comp.slot.assign(static_cast<std::size_t>(rows), std::array<int, 7>{-1, -1, -1, -1, -1, -1, -1});
  const auto& n = grid_.cells();
  for (int r = 0; r < rows; ++r) {
    const long idx = comp.node[static_cast<std::size_t>(r)];
    // The row's distinct columns in order: itself and its active neighbours (a periodic axis of one or two cells
    // makes a neighbour appear twice, or the node its own neighbour).
    std::array<int, 7> neighbour{};
    std::array<int, 7> cols{};
    int count = 0;
    const int self = first_row + r;
    cols[static_cast<std::size_t>(count++)] = self;
    bool interior = true;
    for (int dir = 0; dir < 6; ++dir) {
      const long nb = idx + (dir % 2 == 1 ? 1 : -1) * comp.row.stride(dir / 2);
      const int col = comp.row[static_cast<std::size_t>(nb)];
      neighbour[static_cast<std::size_t>(dir)] = col;
      if (col >= 0) {
        cols[static_cast<std::size_t>(count++)] = col;
      } else {
        interior = false;
      }
    }
    // Insertion into a sorted run of distinct columns (at most 7; std::sort on the partly used array trips GCC 12's
    // -Warray-bounds).
    int distinct = 0;
    for (int q = 0; q < count; ++q) {
      const int col = cols[static_cast<std::size_t>(q)];
      int at = 0;
      while (at < distinct && cols[static_cast<std::size_t>(at)] < col) ++at;
      if (at < distinct && cols[static_cast<std::size_t>(at)] == col) continue;
      for (int s = distinct; s > at; --s) cols[static_cast<std::size_t>(s)] = cols[static_cast<std::size_t>(s) - 1];
      cols[static_cast<std::size_t>(at)] = col;
      ++distinct;
    }
    const int start = m.row_ptr.back();
    const auto position = [&](int col) {
      int at = 0;
      while (cols[static_cast<std::size_t>(at)] != col) ++at;
      return start + at;
    };
    for (int q = 0; q < distinct; ++q) m.cols.push_back(cols[static_cast<std::size_t>(q)]);
    m.row_ptr.push_back(start + distinct);
    auto& slot = comp.slot[static_cast<std::size_t>(r)];
    slot[0] = position(self);
    for (int dir = 0; dir < 6; ++dir) {
      const int col = neighbour[static_cast<std::size_t>(dir)];
      // A one-cell periodic axis makes a node its own neighbour: that link contributes nothing (-2).
      if (col >= 0) slot[static_cast<std::size_t>(dir) + 1] = col == self ? -2 : position(col);
    }
    if (interior) continue;
    const long sx = n[0] + 3;
    const long sy = n[1] + 3;
    const std::array<int, 3> ijk{static_cast<int>(idx % sx) - 1, static_cast<int>((idx / sx) % sy) - 1,
                                 static_cast<int>(idx / (sx * sy)) - 1};
    std::array<NodeLink, 6> links{};
    for (int dir = 0; dir < 6; ++dir) {
      if (neighbour[static_cast<std::size_t>(dir)] < 0) links[static_cast<std::size_t>(dir)] = grid_.link(c, ijk, dir);
    }
    comp.link_id[static_cast<std::size_t>(r)] = static_cast<int>(comp.links.size());
    comp.links.push_back(links);
  }
  m.values.assign(m.cols.size(), 1.0);
  comp.solver = std::make_unique<MomentumSolver>(comm_);
  comp.solver->set_matrix(m);
  // The assembly writes straight into the solver's storage: the slots become places there.
  const std::vector<int>& place = comp.solver->positions();
  for (auto& slot : comp.slot) {
    for (int& s : slot) {
      if (s >= 0) s = place[static_cast<std::size_t>(s)];
    }
  }
  comp.x = Eigen::VectorXd::Zero(rows);
  comp.b = Eigen::VectorXd::Zero(rows);
  comp.a = Eigen::VectorXd::Ones(rows);
  comp.hbya = Eigen::VectorXd::Zero(rows);
}

void FvmSolver::step() {
  const bool rebuild = coefficients_dirty_;
  fill_cell_ghosts(eps_);
  fill_cell_ghosts(ksl_);
  if (rebuild) {
    if (variable_viscosity_) fill_cell_ghosts(visc_);
    // The drive response assembles the drive axis without convection: before the step's own assembly.
    if (drive_.mode == FlowDrive::Mode::flow_rate) compute_drive_response();
  }
  // Assembled once a step: the pressure matrix takes its A (hence rAU, which depends on eps and Ksl) from the
  // same rows the predictor solves.
  for (int c = 0; c < 3; ++c) assemble_momentum(c);
  if (rebuild) {
    build_pressure_matrix();
    coefficients_dirty_ = false;
  }
  stats_ = StepStats{};
  for (int c = 0; c < 3; ++c) {
    if (piso_.momentum_predictor) solve_momentum(c);
  }
  const int correctors = piso_.coupling == PressureCoupling::projection ? 1 : piso_.correctors;
  for (int corr = 0; corr < correctors; ++corr) pressure_corrector(corr + 1 == correctors);
  update_fluxes();
  if (drive_.mode == FlowDrive::Mode::flow_rate) correct_flow_rate();
  update_viscous_force();
  time_s_ += piso_.dt_s;
  ++steps_;
  stats_.courant = courant_number();
  check_state();
}

void FvmSolver::check_state() const {
  bool finite = true;
  for (int c = 0; c < 3; ++c) finite = finite && comp_[static_cast<std::size_t>(c)].x.allFinite();
  // Every rank throws or none does (a rank left behind would wait in the next collective call).
  if (max_over_ranks(finite ? 0.0 : 1.0) > 0.0) {
    throw hs::common::NumericalError(fmt::format("FVM: non-finite velocity at t = {:.6g} s (step {})", time_s_, steps_));
  }
  if (stats_.courant > piso_.max_courant) {
    throw hs::common::NumericalError(fmt::format(
        "FVM: Courant number {:.3g} exceeds max_courant = {:.3g} at t = {:.6g} s (step {}); max |u| = {:.4g} m/s, "
        "dx = {:.4g} m, dt = {:.4g} s: reduce dt_s below {:.4g} s",
        stats_.courant, piso_.max_courant, time_s_, steps_, stats_.courant * h_ / piso_.dt_s, h_, piso_.dt_s,
        piso_.dt_s * piso_.max_courant / stats_.courant));
  }
}

double FvmSolver::courant_number() const {
  double umax = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto& x = comp_[static_cast<std::size_t>(c)].x;
    if (x.size() > 0) umax = std::max(umax, x.cwiseAbs().maxCoeff());
  }
  return max_over_ranks(umax) * piso_.dt_s / h_;
}

void FvmSolver::scatter(int c, const Eigen::VectorXd& values, BlockField<double>& field) const {
  const Component& comp = comp_[static_cast<std::size_t>(c)];
  for (std::size_t r = 0; r < comp.node.size(); ++r) field[static_cast<std::size_t>(comp.node[r])] = values[static_cast<long>(r)];
  fill_velocity_ghosts(c, field);
}

void FvmSolver::fill_velocity_ghosts(int c, BlockField<double>& field) const {
  for (int a = 0; a < 3; ++a) {
    if (!grid_.periodic(a)) fill_velocity_boundary(c, a, field);
    fill_shared_ghosts(field, a);
  }
}

/// The ghosts of velocity component c beyond the box's sides along the non-periodic axis a.
void FvmSolver::fill_velocity_boundary(int c, int a, BlockField<double>& field) const {
  const int n = grid_.cells()[static_cast<std::size_t>(a)];
  if (a == c) {
    // Normal component: faces 0..n are real nodes, the ghosts are -1 and n + 1 (zero gradient).
    const auto st = static_cast<std::size_t>(field.stride(a));
    field.for_each_in_plane(a, -1, [&](std::size_t idx) { field[idx] = field[idx + st]; });
    field.for_each_in_plane(a, n + 1, [&](std::size_t idx) { field[idx] = field[idx - st]; });
    return;
  }
  field.fill_zero_gradient(a);
  // Tangential component beyond a wall: reflect about the wall value, so interpolation sees u_wall there.
  for (int hi = 0; hi < 2; ++hi) {
    const SideCondition& side = grid_.side(a, hi);
    if (side.type != SideType::wall) continue;
    const double wall = 2.0 * side.wall_velocity_m_s[c];
    field.for_each_in_plane(a, hi == 1 ? n : -1, [&](std::size_t idx) { field[idx] = wall - field[idx]; });
    for (const OpenGhost& g : open_ghosts_[static_cast<std::size_t>(c)]) {
      if (g.axis == a && g.high == hi) field[g.ghost] = field[g.interior];
    }
  }
}

void FvmSolver::fill_cell_ghosts(BlockField<double>& field) const {
  for (int a = 0; a < 3; ++a) {
    if (!grid_.periodic(a)) field.fill_zero_gradient(a);
    fill_shared_ghosts(field, a);
  }
}

int FvmSolver::rows_before(int rows) const {
  int before = 0;
  MPI_Exscan(&rows, &before, 1, MPI_INT, MPI_SUM, comm_);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  return rank == 0 ? 0 : before;   // MPI_Exscan leaves rank 0's result undefined
}

double FvmSolver::sum_over_ranks(double local) const {
  double total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return total;
}

double FvmSolver::max_over_ranks(double local) const {
  double most = 0.0;
  MPI_Allreduce(&local, &most, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return most;
}

long FvmSolver::global_node_count(int c, int a) const {
  long count = grid_.node_count(c, a);
  if (grid_.slabs() != nullptr && a == 2) {
    long total = 0;
    MPI_Allreduce(&count, &total, 1, MPI_LONG, MPI_SUM, comm_);
    count = total;
  }
  return count;
}

void FvmSolver::update_fluxes() {
  const double area = h_ * h_;
  for (int c = 0; c < 3; ++c) {
    scatter(c, comp_[static_cast<std::size_t>(c)].x, u_[static_cast<std::size_t>(c)]);
    auto& phi = phi_[static_cast<std::size_t>(c)];
    const auto& u = u_[static_cast<std::size_t>(c)];
    const auto& ap = grid_.apertures(c);
    for (int k = 0; k < grid_.node_count(c, 2); ++k) {
      for (int j = 0; j < grid_.node_count(c, 1); ++j) {
        for (int i = 0; i < grid_.node_count(c, 0); ++i) {
          const std::size_t idx = phi.index(i, j, k);
          phi[idx] = ap[idx] == 0.0 ? 0.0 : face_average(eps_, c, static_cast<long>(idx)) * ap[idx] * area * u[idx];
        }
      }
    }
    for (int a = 0; a < 3; ++a) fill_shared_ghosts(phi, a);
  }
}

double FvmSolver::flow_rate_m3_s(int axis) const {
  const auto& phi = phi_[static_cast<std::size_t>(axis)];
  double sum = 0.0;
  for (int k = 0; k < grid_.node_count(axis, 2); ++k) {
    for (int j = 0; j < grid_.node_count(axis, 1); ++j) {
      for (int i = 0; i < grid_.node_count(axis, 0); ++i) sum += phi(i, j, k);
    }
  }
  return sum_over_ranks(sum) / static_cast<double>(global_node_count(axis, axis));
}

void FvmSolver::correct_flow_rate() {
  const double dg = (drive_.flow_rate_m3_s - flow_rate_m3_s(drive_.axis)) / drive_response_flux_;
  comp_[static_cast<std::size_t>(drive_.axis)].x += dg * drive_response_;
  drive_gradient_ += dg;
  update_fluxes();
}

}  // namespace hs::unresolved
