// SPDX-License-Identifier: MIT
// Removal at openings and injection at inlets, with per-opening counters.
#include "unresolved/dem/opening_traffic.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

double sphere_volume_m3(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

}  // namespace

OpeningTraffic::OpeningTraffic(const OpeningTrafficSpec& spec, const hs::common::Shape& shape, const Domain& domain)
    : openings_(spec.openings), params_(spec.particles) {
  hs::common::check_openings(openings_, shape, domain.box);
  if (spec.discharge_hematocrit.size() != openings_.size()) {
    throw hs::common::ConfigError(fmt::format("{} openings but {} discharge hematocrits: give one per opening",
                                              openings_.size(), spec.discharge_hematocrit.size()));
  }
  for (std::size_t k = 0; k < openings_.size(); ++k) {
    const auto& o = openings_[k];
    counters_.push_back({.name = o.name, .kind = o.kind});
    injectors_.emplace_back();
    if (o.kind != hs::common::OpeningKind::inlet) continue;
    injectors_.back().emplace(InjectionSpec{.inlet = o,
                                            .discharge_hematocrit = spec.discharge_hematocrit[k],
                                            .cell_radius_m = params_.radius_m(),
                                            .seed = spec.seed + k,
                                            .slab_thickness_m = spec.slab_thickness_m},
                              shape, domain);
  }
}

const CellInjector* OpeningTraffic::injector(std::size_t index) const {
  return injectors_.at(index) ? &*injectors_[index] : nullptr;
}

std::int64_t OpeningTraffic::cells_injected() const {
  std::int64_t n = 0;
  for (const auto& c : counters_) n += c.cells_in;
  return n;
}

std::int64_t OpeningTraffic::cells_removed() const {
  std::int64_t n = 0;
  for (const auto& c : counters_) n += c.cells_out;
  return n;
}

void OpeningTraffic::note_ids(const ParticleStore& particles) {
  for (std::size_t i = 0; i < particles.n_owned(); ++i) next_id_ = std::max(next_id_, particles.id()[i] + 1);
}

std::vector<bool> OpeningTraffic::leaving(const ParticleStore& particles) {
  const auto& pos = particles.position_m();
  std::vector<bool> flags;
  for (std::size_t i = 0; i < particles.n_owned(); ++i) {
    const hs::common::Vec3 x{pos[0][i], pos[1][i], pos[2][i]};
    const double r = particles.radius_m()[i];
    for (std::size_t k = 0; k < openings_.size(); ++k) {
      const auto& o = openings_[k];
      if (o.height_m(x) <= 0.0 || o.lateral_m(x) > o.radius_m + r) continue;
      if (flags.empty()) flags.assign(particles.n_owned(), false);
      flags[i] = true;
      ++counters_[k].cells_out;
      counters_[k].rbc_volume_out_m3 += sphere_volume_m3(r);
      break;
    }
  }
  return flags;
}

std::vector<std::vector<NewCell>> OpeningTraffic::planned(const ParticleStore& particles, double dt_s,
                                                          const FluidAtOpenings& fluid) {
  if (fluid.flow_rate_m3_s.size() != openings_.size()) {
    throw std::invalid_argument("OpeningTraffic: one flow rate per opening expected");
  }
  std::vector<std::vector<NewCell>> out(openings_.size());
  for (std::size_t k = 0; k < openings_.size(); ++k) {
    if (!injectors_[k]) continue;
    counters_[k].fluid_volume_in_m3 += fluid.flow_rate_m3_s[k] * dt_s;
    // Inlets see each other's new cells only through `particles`; distinct inlets never share a slab.
    out[k] = injectors_[k]->plan(particles, dt_s, fluid.flow_rate_m3_s[k], fluid.velocity_m_s);
    counters_[k].cells_in += static_cast<std::int64_t>(out[k].size());
    counters_[k].rbc_volume_in_m3 += static_cast<double>(out[k].size()) * sphere_volume_m3(params_.radius_m());
  }
  return out;
}

void OpeningTraffic::exchange(DemSystem& dem, double dt_s, const FluidAtOpenings& fluid) {
  note_ids(dem.particles());
  if (auto flags = leaving(dem.particles()); !flags.empty()) dem.remove_particles(flags);
  const auto cells = planned(dem.particles(), dt_s, fluid);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    for (const NewCell& c : cells[k]) {
      const std::size_t i = dem.insert_particle(c.position_m, c.velocity_m_s, next_id_++);
      dem.particles().inlet_opening()[i] = static_cast<std::int32_t>(k);
    }
  }
}

void OpeningTraffic::exchange(ParticleStore& particles, double dt_s, const FluidAtOpenings& fluid) {
  note_ids(particles);
  if (auto flags = leaving(particles); !flags.empty()) particles.remove_owned(flags);
  const auto cells = planned(particles, dt_s, fluid);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    for (const NewCell& c : cells[k]) {
      particles.add({.position_m = c.position_m,
                     .velocity_m_s = c.velocity_m_s,
                     .angular_velocity_rad_s = {},
                     .radius_m = params_.radius_m(),
                     .mass_kg = params_.mass_kg(),
                     .id = next_id_++,
                     .inlet_opening = static_cast<std::int32_t>(k)});
    }
  }
}

}  // namespace hs::unresolved
