// SPDX-License-Identifier: MIT
// The particle-wall contact loop.
#include "unresolved/dem/wall_contacts.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <cstdint>

#include "unresolved/dem/hertz_kernel.hpp"

namespace hs::unresolved {
namespace {

// Central-difference step for the wall normal, as a fraction of the particle radius: the error of an exact
// distance field is O(h^2) curvature terms (1e-6 relative for a tube of radius >= r), round-off ~1e-13.
constexpr double normal_step_fraction = 1e-3;

}  // namespace

void WallContacts::select_candidates(const ParticleStore& p, double skin_m) {
  candidates_.clear();
  const auto& pos = p.position_m();
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const double phi = shape_.signed_distance({pos[0][i], pos[1][i], pos[2][i]});
    if (phi > -(p.radius_m()[i] + skin_m)) candidates_.push_back(i);
  }
}

hs::common::Vec3 WallContacts::outward_normal(const hs::common::Vec3& x, double h) const {
  hs::common::Vec3 g;
  for (int a = 0; a < 3; ++a) {
    hs::common::Vec3 xp = x, xm = x;
    xp[a] += h;
    xm[a] -= h;
    g[a] = (shape_.signed_distance(xp) - shape_.signed_distance(xm)) / (2.0 * h);
  }
  return hs::common::normalized(g);
}

hs::common::Vec3 WallContacts::outward_normal_at(const hs::common::Vec3& x, double r) const {
  return outward_normal(x, normal_step_fraction * r);
}

std::size_t WallContacts::compute(ParticleStore& p, double dt_s) const {
  auto& pos = p.position_m();
  auto& v = p.velocity_m_s();
  auto& w = p.angular_velocity_rad_s();
  auto& f = p.force_N();
  auto& tq = p.torque_Nm();
  auto& ws = p.wall_shear_m();
  const PairConstants& k = law_.particle_wall();
  const auto n = static_cast<std::int64_t>(candidates_.size());
  std::size_t contacts = 0;
#pragma omp parallel for schedule(static) reduction(+ : contacts) if (n > omp_min_particles)
  for (std::int64_t cc = 0; cc < n; ++cc) {
    const std::size_t i = candidates_[static_cast<std::size_t>(cc)];
    const hs::common::Vec3 x{pos[0][i], pos[1][i], pos[2][i]};
    const double r = p.radius_m()[i];
    const double delta = r + shape_.signed_distance(x);
    double shear[3] = {ws[0][i], ws[1][i], ws[2][i]};
    if (delta <= 0.0) {
      ws[0][i] = ws[1][i] = ws[2][i] = 0.0;
      continue;
    }
    ++contacts;
    const hs::common::Vec3 out = outward_normal(x, normal_step_fraction * r);
    ContactInput c{.n = {-out.x, -out.y, -out.z}, .delta_m = delta, .v_rel = {}, .r_eff_m = r, .m_eff_kg = p.mass_kg()[i]};
    const double rc = r - 0.5 * delta;
    const hs::common::Vec3 wi{w[0][i], w[1][i], w[2][i]};
    const hs::common::Vec3 nn{c.n[0], c.n[1], c.n[2]};
    const hs::common::Vec3 spin = cross(rc * wi, nn);
    for (int a = 0; a < 3; ++a) c.v_rel[a] = v[a][i] - spin[a];
    double ft[3];
    const auto fc = hertz_contact_force(c, k, law_.limit_normal_force(), dt_s, shear, ft);
    const hs::common::Vec3 nxf = cross(nn, {ft[0], ft[1], ft[2]});
    for (int a = 0; a < 3; ++a) {
      f[a][i] += fc[static_cast<std::size_t>(a)];
      tq[a][i] -= rc * nxf[a];
      ws[a][i] = shear[a];
    }
  }
  return contacts;
}

}  // namespace hs::unresolved
