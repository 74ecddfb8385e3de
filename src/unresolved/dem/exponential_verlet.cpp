// SPDX-License-Identifier: MIT
// The exponential (drag-exact) velocity Verlet stages.
#include "unresolved/dem/exponential_verlet.hpp"

#include <cmath>
#include <cstdint>

namespace hs::unresolved {
namespace {

/// (1 - exp(-x)) / x, accurate also for small x (series below 1e-8, where its error is < 1e-16).
inline double phi1(double x) { return x > 1e-8 ? -std::expm1(-x) / x : 1.0 - 0.5 * x; }

}  // namespace

void exponential_half_kick(ParticleStore& p, double h_s) {
  auto& v = p.velocity_m_s();
  auto& w = p.angular_velocity_rad_s();
  const auto& f = p.force_N();
  const auto& tq = p.torque_Nm();
  const auto& beta = p.drag_coefficient_N_s_m();
  const auto& uf = p.fluid_velocity_m_s();
  auto& imp = p.drag_impulse_N_s();
  const double* mass = p.mass_kg().data();
  const double* rad = p.radius_m().data();
  const auto n = static_cast<std::int64_t>(p.n_owned());
#pragma omp parallel for schedule(static)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double inv_m = 1.0 / mass[i];
    const double h_inv_i = h_s * inv_m / (0.4 * rad[i] * rad[i]);
    if (beta[i] == 0.0) {
      for (int a = 0; a < 3; ++a) {
        v[a][i] += h_s * f[a][i] * inv_m;
        w[a][i] += h_inv_i * tq[a][i];
      }
      continue;
    }
    const double g = h_s * phi1(h_s * beta[i] * inv_m);
    for (int a = 0; a < 3; ++a) {
      const double dv = g * (f[a][i] + beta[i] * (uf[a][i] - v[a][i])) * inv_m;
      v[a][i] += dv;
      imp[a][i] += mass[i] * dv - h_s * f[a][i];
      w[a][i] += h_inv_i * tq[a][i];
    }
  }
}

void drift(ParticleStore& p, double dt_s) {
  auto& x = p.position_m();
  const auto& v = p.velocity_m_s();
  const auto n = static_cast<std::int64_t>(p.n_owned());
#pragma omp parallel for schedule(static)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (int a = 0; a < 3; ++a) x[a][i] += dt_s * v[a][i];
  }
}

}  // namespace hs::unresolved
