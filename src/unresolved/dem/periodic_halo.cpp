// SPDX-License-Identifier: MIT
// Periodic wrapping and periodic-image ghosts.
#include "unresolved/dem/periodic_halo.hpp"

#include <cmath>

namespace hs::unresolved {

void wrap_periodic(ParticleStore& particles, const Domain& domain) {
  auto& pos = particles.position_m();
  for (int a = 0; a < 3; ++a) {
    if (!domain.periodic[a]) continue;
    const double lo = domain.box.lo[a];
    const double length = domain.length_m(a);
    for (std::size_t i = 0; i < particles.n_owned(); ++i) {
      double& x = pos[a][i];
      if (x < lo || x >= lo + length) x -= length * std::floor((x - lo) / length);
      if (x >= lo + length) x = lo;   // round-off of the line above
    }
  }
}

void build_periodic_ghosts(ParticleStore& particles, const Domain& domain, double width_m) {
  particles.clear_ghosts();
  for (int a = 0; a < 3; ++a) {
    if (!domain.periodic[a]) continue;
    const double lo = domain.box.lo[a];
    const double hi = domain.box.hi[a];
    const double length = domain.length_m(a);
    const std::size_t n_before = particles.size();
    for (std::size_t i = 0; i < n_before; ++i) {
      const double x = particles.position_m()[a][i];
      const bool ghost = i >= particles.n_owned();
      const std::size_t owner = ghost ? particles.ghost_owner(i) : i;
      const hs::common::Vec3 base = ghost ? particles.ghost_shift_m(i) : hs::common::Vec3{};
      hs::common::Vec3 shift = base;
      if (x < lo + width_m) {
        shift[a] = base[a] + length;
        particles.add_ghost(owner, shift);
      }
      if (x >= hi - width_m) {
        shift[a] = base[a] - length;
        particles.add_ghost(owner, shift);
      }
    }
  }
  particles.update_ghosts();
}

}  // namespace hs::unresolved
