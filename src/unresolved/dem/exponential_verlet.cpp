// SPDX-License-Identifier: MIT
// The exponential (drag-exact) velocity Verlet stages.
#include "unresolved/dem/exponential_verlet.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <cmath>
#include <cstdint>

namespace hs::unresolved {
namespace {

/// (1 - exp(-x)) / x, accurate also for small x (series below 1e-8, where its error is < 1e-16).
inline double phi1(double x) { return x > 1e-8 ? -std::expm1(-x) / x : 1.0 - 0.5 * x; }

/// v += h (f + f_ext) / m and w += h (t + t_ext) / I along one axis: a branch-free loop the compiler vectorises.
/// Orphaned work-sharing: called inside one parallel region for all three axes (fewer fork/joins and barriers).
void plain_kick_axis(std::int64_t n, double h_s, const double* __restrict__ mass, const double* __restrict__ rad,
                     double* __restrict__ v, const double* __restrict__ f, const double* __restrict__ fe,
                     double* __restrict__ w, const double* __restrict__ t, const double* __restrict__ te) {
#pragma omp for simd schedule(static) nowait
  for (std::int64_t i = 0; i < n; ++i) {
    const double hm = h_s / mass[i];
    v[i] += hm * (f[i] + fe[i]);
    w[i] += hm / (0.4 * rad[i] * rad[i]) * (t[i] + te[i]);
  }
}

/// The same without external force and torque (none was ever set): less memory traffic.
void contact_kick_axis(std::int64_t n, double h_s, const double* __restrict__ mass, const double* __restrict__ rad,
                       double* __restrict__ v, const double* __restrict__ f, double* __restrict__ w,
                       const double* __restrict__ t) {
#pragma omp for simd schedule(static) nowait
  for (std::int64_t i = 0; i < n; ++i) {
    const double hm = h_s / mass[i];
    v[i] += hm * f[i];
    w[i] += hm / (0.4 * rad[i] * rad[i]) * t[i];
  }
}

}  // namespace

void exponential_half_kick(ParticleStore& p, double h_s) {
  const auto n = static_cast<std::int64_t>(p.n_owned());
  const double* mass = p.mass_kg().data();
  const double* rad = p.radius_m().data();
  if (!p.drag_used() && !p.external_used()) {
#pragma omp parallel if (n > omp_min_particles)
    for (int a = 0; a < 3; ++a) {
      contact_kick_axis(n, h_s, mass, rad, p.velocity_m_s()[a].data(), p.force_N()[a].data(),
                        p.angular_velocity_rad_s()[a].data(), p.torque_Nm()[a].data());
    }
    return;
  }
  const ParticleStore& cp = p;   // const access: reading does not switch terms on
  if (!p.drag_used()) {
#pragma omp parallel if (n > omp_min_particles)
    for (int a = 0; a < 3; ++a) {
      plain_kick_axis(n, h_s, mass, rad, p.velocity_m_s()[a].data(), p.force_N()[a].data(),
                      cp.external_force_N()[a].data(), p.angular_velocity_rad_s()[a].data(), p.torque_Nm()[a].data(),
                      cp.external_torque_Nm()[a].data());
    }
    return;
  }
  auto& v = p.velocity_m_s();
  auto& w = p.angular_velocity_rad_s();
  auto& imp = p.drag_impulse_N_s();
  const auto& f = p.force_N();
  const auto& fe = cp.external_force_N();
  const auto& tq = p.torque_Nm();
  const auto& te = cp.external_torque_Nm();
  const auto& uf = cp.fluid_velocity_m_s();
  const auto& wf = cp.fluid_angular_velocity_rad_s();
  const double* beta = cp.drag_coefficient_N_s_m().data();
  const double* beta_r = cp.rotational_drag_N_m_s().data();
#pragma omp parallel for schedule(static) if (n > omp_min_particles)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double inv_m = 1.0 / mass[i];
    const double inv_i = inv_m / (0.4 * rad[i] * rad[i]);
    const double g = h_s * phi1(h_s * beta[i] * inv_m);
    const double gr = h_s * phi1(h_s * beta_r[i] * inv_i);   // the rotational relaxation I / beta_r, likewise
    for (int a = 0; a < 3; ++a) {
      const double force = f[a][i] + fe[a][i];
      const double dv = g * (force + beta[i] * (uf[a][i] - v[a][i])) * inv_m;
      v[a][i] += dv;
      imp[a][i] += mass[i] * dv - h_s * force;
      w[a][i] += gr * (tq[a][i] + te[a][i] + beta_r[i] * (wf[a][i] - w[a][i])) * inv_i;
    }
  }
}

void drift(ParticleStore& p, double dt_s) {
  const auto n = static_cast<std::int64_t>(p.n_owned());
#pragma omp parallel if (n > omp_min_particles)
  for (int a = 0; a < 3; ++a) {
    double* __restrict__ x = p.position_m()[a].data();
    const double* __restrict__ v = p.velocity_m_s()[a].data();
#pragma omp for simd schedule(static) nowait
    for (std::int64_t i = 0; i < n; ++i) x[i] += dt_s * v[i];
  }
}

}  // namespace hs::unresolved
