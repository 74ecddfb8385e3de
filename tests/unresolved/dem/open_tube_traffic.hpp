// SPDX-License-Identifier: MIT
// Shared set-up of the injection/removal tests: an open tube with an inlet at x = 0 and an outlet at x = L.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "common/geometry/tube.hpp"
#include "unresolved/dem/opening_traffic.hpp"

namespace hs::unresolved::test {

/// A 20 um tube (D / d = 3.5 for the 94.1 um^3 RBC sphere), 100 um long, along +x.
struct OpenTube {
  double radius_m = 10e-6;
  double length_m = 100e-6;
  hs::common::Tube shape{{.start_m = {0, 0, 0}, .end_m = {100e-6, 0, 0}, .radius_m = 10e-6}};
  Domain domain{.box = shape.bounds(), .periodic = {false, false, false}};

  [[nodiscard]] std::vector<hs::common::Opening> openings() const {
    return {{.name = "in", .kind = hs::common::OpeningKind::inlet, .centre_m = {0, 0, 0}, .normal = {-1, 0, 0},
             .radius_m = radius_m},
            {.name = "out", .kind = hs::common::OpeningKind::outlet, .centre_m = {length_m, 0, 0}, .normal = {1, 0, 0},
             .radius_m = radius_m}};
  }
  [[nodiscard]] double area_m2() const { return std::numbers::pi * radius_m * radius_m; }
  [[nodiscard]] OpeningTrafficSpec spec(double ht_d, std::uint64_t seed) const {
    return {.openings = openings(), .discharge_hematocrit = {ht_d, 0.0}, .particles = default_particle_params(),
            .seed = seed};
  }
};

/// Plug flow U along +x, or Poiseuille flow of mean U: u = 2 U (1 - rho^2 / R^2).
inline VelocityField plug(double u_m_s) {
  return [u_m_s](const hs::common::Vec3&) { return hs::common::Vec3{u_m_s, 0, 0}; };
}
inline VelocityField poiseuille(double mean_m_s, double radius_m) {
  return [=](const hs::common::Vec3& x) {
    const double s = (x.y * x.y + x.z * x.z) / (radius_m * radius_m);
    return hs::common::Vec3{2.0 * mean_m_s * std::max(0.0, 1.0 - s), 0, 0};
  };
}

/// Moves the owned particles by the prescribed velocity (no contacts): x += u(x) dt, v = u(x).
inline void advect(ParticleStore& p, const VelocityField& u, double dt_s) {
  auto& x = p.position_m();
  auto& v = p.velocity_m_s();
  for (std::size_t i = 0; i < p.n_owned(); ++i) {
    const hs::common::Vec3 ui = u({x[0][i], x[1][i], x[2][i]});
    for (int a = 0; a < 3; ++a) {
      x[a][i] += ui[a] * dt_s;
      v[a][i] = ui[a];
    }
  }
}

}  // namespace hs::unresolved::test
