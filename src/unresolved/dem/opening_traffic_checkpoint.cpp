// SPDX-License-Identifier: MIT
// Restart of the cell traffic at the openings: counters, injection debts, random streams, next id.
#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/dem/opening_traffic.hpp"

namespace hs::unresolved {

void OpeningTraffic::write_state(hs::common::Checkpoint& cp, const std::string& prefix) const {
  std::vector<std::int64_t> counts{next_id_};
  std::vector<double> volumes;
  nlohmann::json names = nlohmann::json::array();
  nlohmann::json streams = nlohmann::json::object();
  for (std::size_t k = 0; k < counters_.size(); ++k) {
    const auto& c = counters_[k];
    names.push_back(c.name);
    counts.insert(counts.end(), {c.cells_in, c.cells_out});
    volumes.insert(volumes.end(), {c.rbc_volume_in_m3, c.rbc_volume_out_m3, c.fluid_volume_in_m3,
                                   injectors_[k] ? injectors_[k]->debt_m3() : 0.0});
    if (injectors_[k]) streams[c.name] = injectors_[k]->rng_state();
  }
  cp.put(prefix + "counts", counts);
  cp.put(prefix + "volumes_m3", volumes);
  cp.meta()[prefix + "openings"] = names;
  cp.meta()[prefix + "rng"] = streams;
}

void OpeningTraffic::read_state(const hs::common::Checkpoint& cp, const std::string& prefix) {
  nlohmann::json names = nlohmann::json::array();
  for (const auto& c : counters_) names.push_back(c.name);
  const auto& meta = cp.meta();
  if (!cp.has(prefix + "counts") || !meta.contains(prefix + "openings") || meta.at(prefix + "openings") != names) {
    throw hs::common::ConfigError(fmt::format("checkpoint: the openings saved ({}) are not this case's ({})",
                                              meta.contains(prefix + "openings") ? meta.at(prefix + "openings").dump() : "none",
                                              names.dump()));
  }
  const auto& counts = cp.integers(prefix + "counts");
  const auto& volumes = cp.doubles(prefix + "volumes_m3");
  if (counts.size() != 1 + 2 * counters_.size() || volumes.size() != 4 * counters_.size()) {
    throw hs::common::ConfigError("checkpoint: the cell-traffic arrays have the wrong length");
  }
  next_id_ = counts[0];
  for (std::size_t k = 0; k < counters_.size(); ++k) {
    auto& c = counters_[k];
    c.cells_in = counts[1 + 2 * k];
    c.cells_out = counts[2 + 2 * k];
    c.rbc_volume_in_m3 = volumes[4 * k];
    c.rbc_volume_out_m3 = volumes[4 * k + 1];
    c.fluid_volume_in_m3 = volumes[4 * k + 2];
    if (injectors_[k]) injectors_[k]->restore(volumes[4 * k + 3], meta.at(prefix + "rng").at(c.name).get<std::string>());
  }
}

}  // namespace hs::unresolved
