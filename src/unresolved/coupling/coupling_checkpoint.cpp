// SPDX-License-Identifier: MIT
// CfdDemCoupling restart: fluid, particles and the coupling's own state in one common::Checkpoint.
#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/coupling/cfd_dem_coupling.hpp"
#include "unresolved/dem/dem_checkpoint.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

constexpr std::size_t kStatsValues = 13;   // four Vec3 of ExchangeStats and the lost solid volume

std::vector<double> pack(const ExchangeStats& s, double mean_velocity_m_s) {
  std::vector<double> out;
  for (const Vec3* v : {&s.drag_impulse_particles_N_s, &s.explicit_to_fluid_N_s, &s.received_by_fluid_N_s, &s.pending_N_s}) {
    out.insert(out.end(), {v->x, v->y, v->z});
  }
  out.push_back(s.lost_solid_volume_m3);
  out.push_back(mean_velocity_m_s);
  return out;
}

}  // namespace

void CfdDemCoupling::write_state(hs::common::Checkpoint& cp) const {
  fluid_.write_state(cp, "fluid.");
  write_dem_state(dem_, cp, "dem.");
  cp.put("coupling.eps_old", eps_old_.data());
  std::vector<double> lift;
  for (const Vec3& v : lift_reaction_N_.data()) lift.insert(lift.end(), {v.x, v.y, v.z});
  cp.put("coupling.lift_reaction", lift);
  cp.put("coupling.stats", pack(stats_, mean_velocity_m_s_));
  const std::vector<std::int64_t> steps{steps_};
  cp.put("coupling.steps", steps);
}

void CfdDemCoupling::read_state(const hs::common::Checkpoint& cp) {
  fluid_.read_state(cp, "fluid.");
  read_dem_state(dem_, cp, "dem.");
  const std::vector<double>& eps = cp.doubles("coupling.eps_old");
  const std::vector<double>& lift = cp.doubles("coupling.lift_reaction");
  const std::vector<double>& stats = cp.doubles("coupling.stats");
  const std::vector<std::int64_t>& steps = cp.integers("coupling.steps");
  if (eps.size() != eps_old_.data().size() || lift.size() != 3 * lift_reaction_N_.data().size() ||
      stats.size() != kStatsValues + 1 || steps.size() != 1) {
    throw hs::common::ConfigError("checkpoint: the coupling state does not fit this case (another grid or version)");
  }
  eps_old_.data() = eps;
  for (std::size_t c = 0; c < lift_reaction_N_.data().size(); ++c) lift_reaction_N_.data()[c] = {lift[3 * c], lift[3 * c + 1], lift[3 * c + 2]};
  std::array<Vec3*, 4> v{&stats_.drag_impulse_particles_N_s, &stats_.explicit_to_fluid_N_s, &stats_.received_by_fluid_N_s,
                         &stats_.pending_N_s};
  for (std::size_t k = 0; k < v.size(); ++k) *v[k] = {stats[3 * k], stats[3 * k + 1], stats[3 * k + 2]};
  stats_.lost_solid_volume_m3 = stats[12];
  mean_velocity_m_s_ = stats[kStatsValues];
  steps_ = steps[0];
  map_.locate(dem_.particles());
}

}  // namespace hs::unresolved
