// SPDX-License-Identifier: MIT
// The particle-particle contact loop.
#include "unresolved/dem/pair_contacts.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <algorithm>

#include <omp.h>

#include "unresolved/dem/hertz_kernel.hpp"

namespace hs::unresolved {

void PairContacts::plan(const ParticleStore& p, const NeighborList& list, int n_threads) {
  const auto& off = list.offsets();
  const auto& nbr = list.neighbors();
  const std::size_t n = list.n_owned();
  const std::size_t total = off.empty() ? 0 : off[n];
  ranges_.assign(static_cast<std::size_t>(n_threads), ThreadRange{});
  std::size_t i = 0;
  for (std::size_t t = 0; t < ranges_.size(); ++t) {
    const std::size_t target = total * (t + 1) / ranges_.size();
    const std::size_t lo = i;
    if (t + 1 == ranges_.size()) {
      i = n;
    } else {
      while (i < n && (off[i + 1] <= target || i - lo < 1)) ++i;   // pairs balanced
    }
    std::size_t tlo = lo, thi = i, glo = p.size(), ghi = n;
    for (std::size_t k = off.empty() ? 0 : off[lo]; k < (off.empty() ? 0 : off[i]); ++k) {
      const std::size_t j = nbr[k];
      if (j < n) {
        tlo = std::min(tlo, j);
        thi = std::max(thi, j + 1);
      } else {
        glo = std::min(glo, j);
        ghi = std::max(ghi, j + 1);
      }
    }
    if (ghi == n) glo = n;   // no ghost touched: empty range
    ranges_[t] = {lo, i, tlo, std::max(thi, tlo), glo, ghi};
  }
  buffers_.resize(ranges_.size());
  for (auto& b : buffers_) {
    for (auto& c : b) c.resize(p.size());
  }
  planned_build_ = list.n_builds();
}

std::size_t PairContacts::compute(ParticleStore& p, NeighborList& list, double dt_s) {
  auto& f = p.force_N();
  auto& tq = p.torque_Nm();
  const int n_threads =
      static_cast<std::int64_t>(list.n_owned()) > omp_min_particles ? omp_get_max_threads() : 1;
  if (n_threads == 1) {
    for (int a = 0; a < 3; ++a) {
      std::fill(f[a].begin(), f[a].end(), 0.0);
      std::fill(tq[a].begin(), tq[a].end(), 0.0);
    }
    return compute_range(p, list, dt_s, 0, list.n_owned(),
                         {f[0].data(), f[1].data(), f[2].data(), tq[0].data(), tq[1].data(), tq[2].data()});
  }
  if (planned_build_ != list.n_builds() || ranges_.size() != static_cast<std::size_t>(n_threads) ||
      buffers_.front()[0].size() != p.size()) {
    plan(p, list, n_threads);
  }
  std::size_t contacts = 0;
  const std::size_t n_all = p.size();
#pragma omp parallel num_threads(n_threads) reduction(+ : contacts)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const ThreadRange& r = ranges_[t];
    auto& b = buffers_[t];
    for (auto& c : b) {
      std::fill(c.begin() + static_cast<std::ptrdiff_t>(r.touch_lo), c.begin() + static_cast<std::ptrdiff_t>(r.touch_hi), 0.0);
      std::fill(c.begin() + static_cast<std::ptrdiff_t>(r.ghost_lo), c.begin() + static_cast<std::ptrdiff_t>(r.ghost_hi), 0.0);
    }
    contacts += compute_range(p, list, dt_s, r.i_lo, r.i_hi,
                              {b[0].data(), b[1].data(), b[2].data(), b[3].data(), b[4].data(), b[5].data()});
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n_all; ++k) {   // assigns: the sum of the buffers that touched k, else 0
      double sum[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      for (std::size_t s = 0; s < ranges_.size(); ++s) {
        if (!ranges_[s].touches(k)) continue;
        for (std::size_t a = 0; a < 6; ++a) sum[a] += buffers_[s][a][k];
      }
      for (std::size_t a = 0; a < 3; ++a) {
        f[a][k] = sum[a];
        tq[a][k] = sum[a + 3];
      }
    }
  }
  return contacts;
}

namespace {

/// Raw pointers to the columns the contact loop reads. Stores through the double* force buffers cannot change
/// these pointer values (strict aliasing), so they stay in registers.
struct PairColumns {
  const double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *rad;
};

PairColumns pair_columns(const ParticleStore& p) {
  return {p.position_m()[0].data(), p.position_m()[1].data(), p.position_m()[2].data(),
          p.velocity_m_s()[0].data(), p.velocity_m_s()[1].data(), p.velocity_m_s()[2].data(),
          p.angular_velocity_rad_s()[0].data(), p.angular_velocity_rad_s()[1].data(),
          p.angular_velocity_rad_s()[2].data(), p.radius_m().data()};
}

}  // namespace

std::size_t PairContacts::compute_range(ParticleStore& p, NeighborList& list, double dt_s, std::size_t i_lo,
                                        std::size_t i_hi, std::array<double*, 6> out) const {
  const PairColumns c = pair_columns(p);
  const std::uint32_t* off = list.offsets().data();
  const std::uint32_t* nbr = list.neighbors().data();
  double* shear = list.shear_m().empty() ? nullptr : list.shear_m().front().data();
  const double* eff = list.pair_effective().empty() ? nullptr : list.pair_effective().front().data();
  const PairConstants k = law_.particle_particle();
  const bool limit = law_.limit_normal_force();
  std::size_t contacts = 0;
  for (std::size_t i = i_lo; i < i_hi; ++i) {
    double fi[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};   // force and torque on i
    for (std::uint32_t e = off[i]; e < off[i + 1]; ++e) {
      const std::size_t j = nbr[e];
      const double dx = c.x[i] - c.x[j], dy = c.y[i] - c.y[j], dz = c.z[i] - c.z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double rsum = c.rad[i] + c.rad[j];
      double* s = shear + 3 * static_cast<std::size_t>(e);
      if (r2 >= rsum * rsum) {
        s[0] = s[1] = s[2] = 0.0;
        continue;
      }
      ++contacts;
      const double r = std::sqrt(r2);
      const double inv_r = 1.0 / r;
      const double delta = rsum - r;
      ContactInput in{.n = {dx * inv_r, dy * inv_r, dz * inv_r}, .delta_m = delta, .v_rel = {},
                      .r_eff_m = eff[2 * e], .m_eff_kg = eff[2 * e + 1]};
      const double ric = c.rad[i] - 0.5 * delta, rjc = c.rad[j] - 0.5 * delta;
      const double wsx = ric * c.wx[i] + rjc * c.wx[j], wsy = ric * c.wy[i] + rjc * c.wy[j],
                   wsz = ric * c.wz[i] + rjc * c.wz[j];
      in.v_rel[0] = c.vx[i] - c.vx[j] - (wsy * in.n[2] - wsz * in.n[1]);
      in.v_rel[1] = c.vy[i] - c.vy[j] - (wsz * in.n[0] - wsx * in.n[2]);
      in.v_rel[2] = c.vz[i] - c.vz[j] - (wsx * in.n[1] - wsy * in.n[0]);
      double ft[3];
      const auto fc = hertz_contact_force(in, k, limit, dt_s, s, ft);
      // Torque about each centre: contact point at -ric n from i and +rjc n from j; both = -r_c (n x F_t).
      const double nxf[3] = {in.n[1] * ft[2] - in.n[2] * ft[1], in.n[2] * ft[0] - in.n[0] * ft[2],
                             in.n[0] * ft[1] - in.n[1] * ft[0]};
      for (std::size_t a = 0; a < 3; ++a) {
        fi[a] += fc[a];
        out[a][j] -= fc[a];
        fi[a + 3] -= ric * nxf[a];
        out[a + 3][j] -= rjc * nxf[a];
      }
    }
    for (std::size_t a = 0; a < 6; ++a) out[a][i] += fi[a];
  }
  return contacts;
}

}  // namespace hs::unresolved
