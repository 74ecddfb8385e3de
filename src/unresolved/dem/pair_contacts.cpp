// SPDX-License-Identifier: MIT
// The particle-particle contact loop.
#include "unresolved/dem/pair_contacts.hpp"

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
    std::size_t tlo = lo, thi = i;
    for (std::size_t k = off.empty() ? 0 : off[lo]; k < (off.empty() ? 0 : off[i]); ++k) {
      tlo = std::min<std::size_t>(tlo, nbr[k]);
      thi = std::max<std::size_t>(thi, nbr[k] + 1);
    }
    ranges_[t] = {lo, i, tlo, std::max(thi, tlo)};
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
  const int n_threads = omp_get_max_threads();
  for (int a = 0; a < 3; ++a) {
    std::fill(f[a].begin(), f[a].end(), 0.0);
    std::fill(tq[a].begin(), tq[a].end(), 0.0);
  }
  if (n_threads == 1) {
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
    for (auto& c : b) std::fill(c.begin() + static_cast<std::ptrdiff_t>(r.touch_lo), c.begin() + static_cast<std::ptrdiff_t>(r.touch_hi), 0.0);
    contacts += compute_range(p, list, dt_s, r.i_lo, r.i_hi,
                              {b[0].data(), b[1].data(), b[2].data(), b[3].data(), b[4].data(), b[5].data()});
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n_all; ++k) {
      for (std::size_t s = 0; s < ranges_.size(); ++s) {
        if (k < ranges_[s].touch_lo || k >= ranges_[s].touch_hi) continue;
        for (int a = 0; a < 3; ++a) {
          f[a][k] += buffers_[s][static_cast<std::size_t>(a)][k];
          tq[a][k] += buffers_[s][static_cast<std::size_t>(a) + 3][k];
        }
      }
    }
  }
  return contacts;
}

std::size_t PairContacts::compute_range(ParticleStore& p, NeighborList& list, double dt_s, std::size_t i_lo,
                                        std::size_t i_hi, std::array<double*, 6> out) const {
  const double* x = p.position_m()[0].data();
  const double* y = p.position_m()[1].data();
  const double* z = p.position_m()[2].data();
  const auto& v = p.velocity_m_s();
  const auto& w = p.angular_velocity_rad_s();
  const double* rad = p.radius_m().data();
  const double* mass = p.mass_kg().data();
  const auto& off = list.offsets();
  const auto& nbr = list.neighbors();
  auto& shear = list.shear_m();
  const PairConstants& k = law_.particle_particle();
  const bool limit = law_.limit_normal_force();
  std::size_t contacts = 0;
  for (std::size_t i = i_lo; i < i_hi; ++i) {
    double fi[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0};
    for (std::uint32_t e = off[i]; e < off[i + 1]; ++e) {
      const std::size_t j = nbr[e];
      const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double rsum = rad[i] + rad[j];
      if (r2 >= rsum * rsum) {
        shear[e] = {0.0, 0.0, 0.0};
        continue;
      }
      ++contacts;
      const double r = std::sqrt(r2);
      const double delta = rsum - r;
      ContactInput c{.n = {dx / r, dy / r, dz / r}, .delta_m = delta, .v_rel = {},
                     .r_eff_m = rad[i] * rad[j] / rsum, .m_eff_kg = mass[i] * mass[j] / (mass[i] + mass[j])};
      const double ric = rad[i] - 0.5 * delta, rjc = rad[j] - 0.5 * delta;
      const double ws[3] = {ric * w[0][i] + rjc * w[0][j], ric * w[1][i] + rjc * w[1][j], ric * w[2][i] + rjc * w[2][j]};
      c.v_rel[0] = v[0][i] - v[0][j] - (ws[1] * c.n[2] - ws[2] * c.n[1]);
      c.v_rel[1] = v[1][i] - v[1][j] - (ws[2] * c.n[0] - ws[0] * c.n[2]);
      c.v_rel[2] = v[2][i] - v[2][j] - (ws[0] * c.n[1] - ws[1] * c.n[0]);
      double ft[3];
      const auto fc = hertz_contact_force(c, k, limit, dt_s, shear[e].data(), ft);
      // Torque about each centre: contact point at -ric n from i and +rjc n from j; both = -r_c (n x F_t).
      const double nxf[3] = {c.n[1] * ft[2] - c.n[2] * ft[1], c.n[2] * ft[0] - c.n[0] * ft[2],
                             c.n[0] * ft[1] - c.n[1] * ft[0]};
      for (int a = 0; a < 3; ++a) {
        fi[a] += fc[static_cast<std::size_t>(a)];
        out[static_cast<std::size_t>(a)][j] -= fc[static_cast<std::size_t>(a)];
        ti[a] -= ric * nxf[a];
        out[static_cast<std::size_t>(a) + 3][j] -= rjc * nxf[a];
      }
    }
    for (int a = 0; a < 3; ++a) {
      out[static_cast<std::size_t>(a)][i] += fi[a];
      out[static_cast<std::size_t>(a) + 3][i] += ti[a];
    }
  }
  return contacts;
}

}  // namespace hs::unresolved
