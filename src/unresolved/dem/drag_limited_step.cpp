// SPDX-License-Identifier: MIT
// The drag-limited DEM step: a Gershgorin bound on the overdamped contact network's relaxation rate.
#include "unresolved/dem/drag_limited_step.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace hs::unresolved {
namespace {

/// The Hertz overlap under a normal force F: F = (4/3) Y* sqrt(R*) delta^(3/2).
double hertz_overlap_m(double force_N, double y_eff_Pa, double r_eff_m) {
  return std::pow(0.75 * force_N / (y_eff_Pa * std::sqrt(r_eff_m)), 2.0 / 3.0);
}

/// Rate and dashpot number of one contact at overlap delta, given both sides' mobilities.
struct ContactRate {
  double rate_1_s;
  double damping;
};

ContactRate contact_rate(const PairConstants& k, double r_eff_m, double m_eff_kg, double delta_m, double mob_n,
                         double mob_t) {
  const double a = std::sqrt(r_eff_m * delta_m);
  const double kn = 2.0 * k.y_eff_Pa * a;
  const double kt = 8.0 * k.g_eff_Pa * a;
  const double sqrt_ma = std::sqrt(m_eff_kg * a);
  return {std::max(kn * mob_n, kt * mob_t), std::max(k.damping_n * sqrt_ma * mob_n, k.damping_t * sqrt_ma * mob_t)};
}

}  // namespace

DragLimitedStep drag_limited_step(const ParticleStore& p, const NeighborList& list, const HertzContactLaw& law,
                                  const WallContacts* walls, const DemSlabs* slabs) {
  DragLimitedStep out;
  const std::size_t n = p.n_owned();
  // Every rank gives up or none does (the others would wait in the fold below).
  const auto on_any_rank = [slabs](bool mine) { return slabs != nullptr ? slabs->any(mine) : mine; };
  if (on_any_rank(!p.drag_used())) {
    out.reason = "no drag on the particles";
    return out;
  }
  const auto& beta = p.drag_coefficient_N_s_m();
  const auto& beta_r = p.rotational_drag_N_m_s();
  const auto& rad = p.radius_m();
  const auto& mass = p.mass_kg();
  bool undragged = false;
  for (std::size_t i = 0; i < n && !undragged; ++i) {
    undragged = !(beta[i] > 0.0) || !(beta_r[i] > 0.0);
    if (!undragged) {
      out.inertial_time_s = std::max({out.inertial_time_s, mass[i] / beta[i], 0.4 * mass[i] * rad[i] * rad[i] / beta_r[i]});
    }
  }
  if (on_any_rank(undragged)) {
    out.reason = "a particle without translational or rotational drag";
    out.inertial_time_s = 0.0;
    return out;
  }
  // Per-particle mobilities and free drift, owned and ghosts (an image takes its owner's, another rank's copy
  // carries its own).
  const std::size_t n_all = p.size();
  std::vector<double> mob_n(n_all), mob_t(n_all);
  std::vector<std::array<double, 3>> drift(n_all);
  const auto& uf = p.fluid_velocity_m_s();
  const auto& fe = p.external_force_N();
  for (std::size_t k = 0; k < n_all; ++k) {
    const std::size_t o = p.coupling_row(k);
    mob_n[k] = 1.0 / beta[o];
    mob_t[k] = mob_n[k] + rad[o] * rad[o] / beta_r[o];
    for (std::size_t a = 0; a < 3; ++a) drift[k][a] = uf[a][o] + fe[a][o] * mob_n[k];
  }
  const auto& x = p.position_m();
  const std::uint32_t* off = list.offsets().data();
  const std::uint32_t* nbr = list.neighbors().data();
  const auto& eff = list.pair_effective();
  const PairConstants& kpp = law.particle_particle();
  // Per-thread sums over contiguous ranges of i, added in thread order: the same bound run to run.
  const int n_threads = static_cast<std::int64_t>(n) > omp_min_particles ? omp_get_max_threads() : 1;
  std::vector<std::vector<double>> sums(static_cast<std::size_t>(n_threads));
  std::vector<double> damping(static_cast<std::size_t>(n_threads), 0.0);
  const std::size_t n_listed = list.n_owned();
#pragma omp parallel num_threads(n_threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<double>& sum = sums[t];
    sum.assign(n_all, 0.0);
    double d_max = 0.0;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n_listed; ++i) {
      for (std::uint32_t e = off[i]; e < off[i + 1]; ++e) {
        const std::size_t j = nbr[e];
        const double d[3] = {x[0][i] - x[0][j], x[1][i] - x[1][j], x[2][i] - x[2][j]};
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double mn = mob_n[i] + mob_n[j];
        double closing = 0.0;   // speed at which the free drifts press the pair together
        if (r > 0.0) {
          for (std::size_t a = 0; a < 3; ++a) closing -= (drift[i][a] - drift[j][a]) * d[a] / r;
        }
        const double r_eff = eff[e][0];
        const double delta = std::max(rad[i] + rad[j] - r, closing > 0.0 ? hertz_overlap_m(closing / mn, kpp.y_eff_Pa, r_eff) : 0.0);
        if (!(delta > 0.0)) continue;
        const ContactRate c = contact_rate(kpp, r_eff, eff[e][1], delta, mn, mob_t[i] + mob_t[j]);
        sum[i] += c.rate_1_s;
        sum[j] += c.rate_1_s;
        d_max = std::max(d_max, c.damping);
      }
    }
    damping[t] = d_max;
  }
  std::vector<double> total(n_all, 0.0);
  for (const auto& s : sums) {
    for (std::size_t k = 0; k < n_all; ++k) total[k] += s[k];
  }
  if (slabs != nullptr) slabs->fold_values(total);   // first: another rank's copy may be of an image here
  for (std::size_t k = n; k < n_all; ++k) {
    if (p.ghost_owner(k) != ParticleStore::remote_owner) total[p.ghost_owner(k)] += total[k];
  }
  for (const double d : damping) out.damping_number = std::max(out.damping_number, d);
  if (walls != nullptr) {
    const PairConstants& kpw = law.particle_wall();
    for (const std::size_t i : walls->candidates()) {
      const hs::common::Vec3 xi{x[0][i], x[1][i], x[2][i]};
      const hs::common::Vec3 out_n = walls->outward_normal_at(xi, rad[i]);
      const double closing = drift[i][0] * out_n.x + drift[i][1] * out_n.y + drift[i][2] * out_n.z;
      const double delta = std::max(walls->overlap_m(xi, rad[i]),
                                    closing > 0.0 ? hertz_overlap_m(closing / mob_n[i], kpw.y_eff_Pa, rad[i]) : 0.0);
      if (!(delta > 0.0)) continue;
      const ContactRate c = contact_rate(kpw, rad[i], mass[i], delta, mob_n[i], mob_t[i]);
      total[i] += c.rate_1_s;
      out.damping_number = std::max(out.damping_number, c.damping);
    }
  }
  for (std::size_t i = 0; i < n; ++i) out.rate_bound_1_s = std::max(out.rate_bound_1_s, total[i]);
  if (slabs != nullptr) {
    out.rate_bound_1_s = slabs->max(out.rate_bound_1_s);
    out.damping_number = slabs->max(out.damping_number);
    out.inertial_time_s = slabs->max(out.inertial_time_s);
  }
  out.time_step_s = out.rate_bound_1_s > 0.0 ? drag_limited_step_fraction / out.rate_bound_1_s
                                             : std::numeric_limits<double>::infinity();
  if (out.damping_number > drag_limited_max_damping_number) {
    out.reason = "a contact dashpot too strong against the drag";
  } else if (out.rate_bound_1_s * out.inertial_time_s > drag_limited_max_rate_times_tau) {
    out.reason = "a contact not overdamped";
  } else {
    out.applies = true;
  }
  return out;
}

}  // namespace hs::unresolved
