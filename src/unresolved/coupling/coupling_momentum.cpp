// SPDX-License-Identifier: MIT
// The coupling's momentum bookkeeping: what the fluid received, the fluid's and the particles' momenta, and the sums
// over the ranks on slabs.
#include <cmath>

#include <mpi.h>

#include "unresolved/coupling/cfd_dem_coupling.hpp"

namespace hs::unresolved {

using hs::common::Vec3;

Vec3 CfdDemCoupling::summed(Vec3 v) const {
  if (slabs_ != nullptr) MPI_Allreduce(MPI_IN_PLACE, &v[0], 3, MPI_DOUBLE, MPI_SUM, slabs_->comm());
  return v;
}

double CfdDemCoupling::summed(double x) const {
  if (slabs_ != nullptr) MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_SUM, slabs_->comm());
  return x;
}

long CfdDemCoupling::summed(long n) const {
  if (slabs_ != nullptr) MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG, MPI_SUM, slabs_->comm());
  return n;
}

Vec3 CfdDemCoupling::fluid_momentum_kg_m_s() const {
  const FvmGrid& grid = fluid_.grid();
  const BlockField<double>& eps = fluid_.void_fraction();
  const double v_cell = std::pow(grid.dx_m(), 3);
  Vec3 total{};
  for (int c = 0; c < 3; ++c) {
    const BlockField<double>& u = fluid_.face_velocity(c);
    const int ni = grid.node_count(c, 0);
    const int nj = grid.node_count(c, 1);
    const int nk = grid.node_count(c, 2);
    for (int k = 0; k < nk; ++k) {
      for (int j = 0; j < nj; ++j) {
        for (int i = 0; i < ni; ++i) {
          if (grid.kind(c, i, j, k) != NodeKind::active) continue;
          const std::size_t idx = u.index(i, j, k);
          const double e = 0.5 * (eps[idx - static_cast<std::size_t>(eps.stride(c))] + eps[idx]);
          total[c] += fluid_.fluid().density_kg_m3 * e * u[idx] * v_cell;
        }
      }
    }
  }
  return summed(total);
}

Vec3 CfdDemCoupling::received_by_fluid_N_s() const {
  // The exchange terms of the solver's momentum row, (Ksl_f (Us_f - u_f) + f_f) dx^3 dt, with its face averages.
  const FvmGrid& grid = fluid_.grid();
  const BlockField<double>& ksl = fluid_.implicit_coefficient_kg_m3_s();
  const BlockField<Vec3>& us = fluid_.particle_velocity_m_s();
  const BlockField<Vec3>& f = fluid_.explicit_force_density_N_m3();
  const double vdt = std::pow(grid.dx_m(), 3) * fluid_.settings().dt_s;
  Vec3 total{};
  for (int c = 0; c < 3; ++c) {
    const BlockField<double>& u = fluid_.face_velocity(c);
    const auto sc = static_cast<std::size_t>(u.stride(c));
    for (int k = 0; k < grid.node_count(c, 2); ++k) {
      for (int j = 0; j < grid.node_count(c, 1); ++j) {
        for (int i = 0; i < grid.node_count(c, 0); ++i) {
          if (grid.kind(c, i, j, k) != NodeKind::active) continue;
          const std::size_t idx = u.index(i, j, k);
          const double ks = 0.5 * (ksl[idx - sc] + ksl[idx]);
          const double usf = 0.5 * (us[idx - sc][c] + us[idx][c]);
          const double ff = 0.5 * (f[idx - sc][c] + f[idx][c]);
          total[c] += (ks * (usf - u[idx]) + ff) * vdt;
        }
      }
    }
  }
  return summed(total);
}

Vec3 CfdDemCoupling::particle_momentum_kg_m_s() const {
  const ParticleStore& p = dem_.particles();
  Vec3 total{};
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    total += p.mass_kg()[i] * Vec3{p.velocity_m_s()[0][i], p.velocity_m_s()[1][i], p.velocity_m_s()[2][i]};
  }
  return summed(total);
}

}  // namespace hs::unresolved
