// SPDX-License-Identifier: MIT
// Global diagnostics of the fluid lattice: macroscopic fields, total mass and the numerical watchdog.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/parallel/reductions.hpp"
#include "resolved/lbm/fluid_lattice.hpp"

namespace hs::resolved {

void FluidLattice::macroscopic(std::vector<double>& rho, std::vector<double>& u_xyz) const {
  rho.assign(layout_.interior_volume(), spec_.rho0_lu);
  u_xyz.assign(3 * layout_.interior_volume(), 0.0);
  std::size_t k = 0;
  for (int z = 0; z < layout_.n[2]; ++z) {
    for (int y = 0; y < layout_.n[1]; ++y) {
      for (int x = 0; x < layout_.n[0]; ++x, ++k) {
        if (!is_fluid(x, y, z)) continue;
        const NodeMoments m = moments(x, y, z);
        rho[k] = m.rho;
        u_xyz[3 * k] = m.u.x;
        u_xyz[3 * k + 1] = m.u.y;
        u_xyz[3 * k + 2] = m.u.z;
      }
    }
  }
}

double FluidLattice::total_mass() const {
  double local = 0.0;
  for (int z = 0; z < layout_.n[2]; ++z) {
    for (int y = 0; y < layout_.n[1]; ++y) {
      for (int x = 0; x < layout_.n[0]; ++x) {
        if (!is_fluid(x, y, z)) continue;
        for (int i = 0; i < D3Q19::q; ++i) local += population(x, y, z, i);
      }
    }
  }
  return common::global_sum(local, decomposition_->comm());
}

/// f_i(n) = table[i][n]: where the scheme keeps the pre-collision populations (see population()), except, with AA
/// in the swapped layout and x wrapping, at the ends of a row.
std::array<const double*, D3Q19::q> FluidLattice::population_table() const {
  std::array<const double*, D3Q19::q> table{};
  for (int i = 0; i < D3Q19::q; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const bool natural = aa() && steps_ % 2 == 1;
    const auto component = static_cast<std::size_t>(aa() && !natural ? D3Q19::opposite(i) : i);
    table[ii] = src_.data() + component * stride_ - (natural ? 0 : offsets_[ii]);
  }
  return table;
}

void FluidLattice::check_health(const HealthLimits& limits) const {
  std::string problem;
  const double cs = std::sqrt(D3Q19::cs2);
  const auto& off = decomposition_->offset();
  // A pass over the runs with the populations read in place: through population() per node it cost 5 % of a cell
  // run, once per sample.
  const auto table = population_table();
  const bool wrapped_ends = aa() && aa_wrap_x() > 0 && steps_ % 2 == 0;
  const std::size_t v = layout_.volume();
  for (const FluidRun& run : runs_) {
    for (std::ptrdiff_t n = run.begin; n < run.begin + run.length; ++n) {
      NodeMoments m;
      if (wrapped_ends && (n == run.begin || n == run.begin + run.length - 1)) {
        const auto c = layout_.coords(n);
        m = moments(c[0], c[1], c[2]);
      } else {
        Populations f{};
        for (std::size_t i = 0; i < D3Q19::q; ++i) f[i] = table[i][n];
        common::Vec3 force = body_force_;
        if (!force_field_.empty()) {
          const auto k = static_cast<std::size_t>(n);
          force += common::Vec3{force_field_[k], force_field_[v + k], force_field_[2 * v + k]};
        }
        m = resolved::moments(f, force);
      }
      const double mach = norm(m.u) / cs;
      const bool healthy = std::isfinite(m.rho) && std::isfinite(mach) && m.rho >= limits.rho_min_lu &&
                           m.rho <= limits.rho_max_lu && mach <= limits.mach_max;
      if (healthy) continue;
      const auto c = layout_.coords(n);
      const auto where = fmt::format("step {}, global node ({}, {}, {})", steps_, c[0] + off[0], c[1] + off[1], c[2] + off[2]);
      if (!std::isfinite(m.rho) || !std::isfinite(mach)) {
        problem = fmt::format("{}: not a number (rho = {}, u = ({}, {}, {}))", where, m.rho, m.u.x, m.u.y, m.u.z);
      } else if (m.rho < limits.rho_min_lu || m.rho > limits.rho_max_lu) {
        problem = fmt::format("{}: density {:.6g} (lattice units) outside [{}, {}]", where, m.rho, limits.rho_min_lu,
                              limits.rho_max_lu);
      } else {
        problem = fmt::format("{}: lattice Mach number |u|/c_s = {:.4f} > {} (|u| = {:.4g} lattice units); "
                              "reduce the velocity or dx, or raise tau",
                              where, mach, limits.mach_max, norm(m.u));
      }
      break;
    }
    if (!problem.empty()) break;
  }
  // Every rank throws the same message: the one of the highest rank that found a problem, broadcast from it.
  const MPI_Comm comm = decomposition_->comm();
  const int mine = problem.empty() ? -1 : decomposition_->rank();
  int source = -1;
  MPI_Allreduce(&mine, &source, 1, MPI_INT, MPI_MAX, comm);
  if (source < 0) return;
  int length = static_cast<int>(problem.size());
  MPI_Bcast(&length, 1, MPI_INT, source, comm);
  problem.resize(static_cast<std::size_t>(length));
  MPI_Bcast(problem.data(), length, MPI_CHAR, source, comm);
  throw common::NumericalError("lattice Boltzmann watchdog: " + problem);
}

}  // namespace hs::resolved
