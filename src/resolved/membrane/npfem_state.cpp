// SPDX-License-Identifier: MIT
// npFEM solver checkpoint: the state (positions, velocities, forces, centre) and the solver's memory, so that a
// resumed run repeats the uninterrupted one bit for bit.
#include <stdexcept>

#include "resolved/membrane/npfem_solver.hpp"
#include "resolved/membrane/npfem_workspace.hpp"

namespace hs::resolved {

std::vector<double> NpfemSolver::state() const {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(9 * x_um_.rows() + 3));
  for (const Positions* p : {&x_um_, &v_um_us_, &f_ext_pN_}) {
    for (Eigen::Index i = 0; i < p->rows(); ++i)
      for (int a = 0; a < 3; ++a) out.push_back((*p)(i, a));
  }
  for (int a = 0; a < 3; ++a) out.push_back(center_target_um_[a]);
  out.push_back(static_cast<double>(work_->corrections));
  for (int k = 0; k < work_->corrections; ++k)
    for (Eigen::Index i = 0; i < x_um_.rows(); ++i)
      for (int a = 0; a < 3; ++a) out.push_back(work_->correction[k](i, a));
  work_->history.save(out);
  if (step_proxy_) {   // the proxy's age and geometry: a resumed run refactorises where the original did
    out.push_back(static_cast<double>(step_proxy_age_));
    const Positions& p = step_proxy_->frozen_at();
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      for (int a = 0; a < 3; ++a) out.push_back(p(i, a));
  }
  return out;
}

void NpfemSolver::restore_state(std::span<const double> state) {
  const auto n = static_cast<std::size_t>(x_um_.rows());
  if (state.size() < 9 * n + 3) throw std::invalid_argument("NpfemSolver::restore_state: the checkpoint is of another mesh");
  std::size_t k = 0;
  for (Positions* p : {&x_um_, &v_um_us_, &f_ext_pN_}) {
    p->resize(static_cast<Eigen::Index>(n), 3);
    for (Eigen::Index i = 0; i < p->rows(); ++i)
      for (int a = 0; a < 3; ++a) (*p)(i, a) = state[k++];
  }
  for (int a = 0; a < 3; ++a) center_target_um_[a] = state[k++];
  restore_memory(state.subspan(k));
}

std::vector<double> NpfemSolver::statistics_state() const {
  const NpfemStatistics& s = stats_;
  return {static_cast<double>(s.steps), static_cast<double>(s.iterations), static_cast<double>(s.unconverged_steps),
          static_cast<double>(s.line_search_stops), static_cast<double>(s.iteration_cap_stops),
          s.unconverged_gradient_sum, s.viscous_dissipation_J, s.external_work_J, s.elastic_work_J,
          s.damping_dissipation_J, s.kinetic_step_loss_J, s.solver_residual_work_J};
}

void NpfemSolver::restore_statistics(std::span<const double> state) {
  if (state.size() != statistics_state().size()) {
    throw std::invalid_argument("NpfemSolver::restore_statistics: the checkpoint's statistics have another layout");
  }
  NpfemStatistics& s = stats_;
  s.steps = static_cast<long>(state[0]);
  s.iterations = static_cast<long>(state[1]);
  s.unconverged_steps = static_cast<long>(state[2]);
  s.line_search_stops = static_cast<long>(state[3]);
  s.iteration_cap_stops = static_cast<long>(state[4]);
  s.unconverged_gradient_sum = state[5];
  s.viscous_dissipation_J = state[6];
  s.external_work_J = state[7];
  s.elastic_work_J = state[8];
  s.damping_dissipation_J = state[9];
  s.kinetic_step_loss_J = state[10];
  s.solver_residual_work_J = state[11];
}

void NpfemSolver::restore_memory(std::span<const double> memory) {
  Workspace& w = *work_;
  w.corrections = 0;
  w.history.clear();
  if (step_proxy_) step_proxy_age_ = settings_.viscous_proxy_refresh_steps;   // refactorise at the next step
  if (memory.empty()) return;   // a state without the solver memory: start afresh
  const auto n = static_cast<std::size_t>(x_um_.rows());
  const auto corrections = static_cast<int>(memory[0]);
  if (corrections < 0 || corrections > 2 || memory.size() < 1 + 3 * n * static_cast<std::size_t>(corrections)) {
    throw std::invalid_argument("NpfemSolver::restore_state: the checkpoint is of another mesh or solver");
  }
  std::size_t k = 1;
  for (int c = 0; c < corrections; ++c)
    for (Eigen::Index i = 0; i < x_um_.rows(); ++i)
      for (int a = 0; a < 3; ++a) w.correction[c](i, a) = memory[k++];
  k += w.history.restore(memory.subspan(k));
  const std::size_t proxy_size = step_proxy_ ? 1 + 3 * n : 0;
  if (memory.size() - k != proxy_size) {
    throw std::invalid_argument("NpfemSolver::restore_state: the checkpoint is of another mesh or solver");
  }
  w.corrections = corrections;
  if (step_proxy_) {
    const auto age = static_cast<int>(memory[k++]);
    Positions p(static_cast<Eigen::Index>(n), 3);
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      for (int a = 0; a < 3; ++a) p(i, a) = memory[k++];
    refresh_step_proxy(p);
    step_proxy_age_ = age;
  }
}

}  // namespace hs::resolved
