// SPDX-License-Identifier: MIT
// Removal at openings and injection at inlets, with per-opening counters.
#include "unresolved/dem/opening_traffic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <mpi.h>

#include "common/errors.hpp"

namespace hs::unresolved {
namespace {

double sphere_volume_m3(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

}  // namespace

OpeningTraffic::OpeningTraffic(const OpeningTrafficSpec& spec, const hs::common::Shape& shape, const Domain& domain,
                               const DemSlabs* slabs)
    : openings_(spec.openings), params_(spec.particles), slabs_(slabs) {
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
  injects_here_.assign(openings_.size(), slabs_ == nullptr);
  if (slabs_ != nullptr) place_inlets(spec);
}

void OpeningTraffic::place_inlets(const OpeningTrafficSpec& spec) {
  // The injection region (depth r .. r + slab inside the inlet plane, InjectionSpec) and a cut-off beyond it.
  const double r = params_.radius_m();
  const double depth = r + (spec.slab_thickness_m > 0.0 ? spec.slab_thickness_m : 2.0 * r);
  const double reach = depth + 2.0 * r + params_.skin_m;
  std::string refused;
  for (std::size_t k = 0; k < openings_.size(); ++k) {
    const hs::common::Opening& o = openings_[k];
    if (!injectors_[k]) continue;
    if (std::abs(std::abs(o.normal.z) - 1.0) > 1e-12) {
      refused = fmt::format("opening '{}': on several ranks an inlet must face along z (its normal is ({:.3g}, {:.3g}, "
                            "{:.3g})): run on one rank", o.name, o.normal.x, o.normal.y, o.normal.z);
      continue;
    }
    const double inward = -o.normal.z;   // the region lies on this side of the plane
    const double middle = o.centre_m.z + inward * 0.5 * depth;
    if (middle < slabs_->lo_m() || middle >= slabs_->hi_m()) continue;   // another rank's inlet
    injects_here_[k] = true;
    const double far = o.centre_m.z + inward * reach;
    if (far < slabs_->lo_m() || far > slabs_->hi_m()) {
      refused = fmt::format("opening '{}': the slab holding this inlet ({:.4g} to {:.4g} m along z) is thinner than its "
                            "injection region and a cut-off ({:.4g} m): use fewer ranks", o.name, slabs_->lo_m(),
                            slabs_->hi_m(), reach);
    }
  }
  if (slabs_->any(!refused.empty())) {
    throw hs::common::ConfigError(refused.empty() ? "an inlet does not fit its slab on another rank" : refused);
  }
}

std::vector<OpeningCounters> OpeningTraffic::summed_counters() const {
  std::vector<OpeningCounters> out = counters_;
  if (slabs_ == nullptr) return out;
  std::vector<double> values;
  for (const OpeningCounters& c : out) {
    values.insert(values.end(), {static_cast<double>(c.cells_in), static_cast<double>(c.cells_out), c.rbc_volume_in_m3,
                                 c.rbc_volume_out_m3, c.fluid_volume_in_m3});
  }
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, slabs_->comm());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double* v = values.data() + 5 * k;
    out[k].cells_in = static_cast<std::int64_t>(v[0]);
    out[k].cells_out = static_cast<std::int64_t>(v[1]);
    out[k].rbc_volume_in_m3 = v[2];
    out[k].rbc_volume_out_m3 = v[3];
    out[k].fluid_volume_in_m3 = v[4];
  }
  return out;
}

const CellInjector* OpeningTraffic::injector(std::size_t index) const {
  return injectors_.at(index) && injects_here_[index] ? &*injectors_[index] : nullptr;
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
    if (!injectors_[k] || !injects_here_[k]) continue;
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
  if (slabs_ != nullptr) next_id_ = static_cast<std::int64_t>(slabs_->max(static_cast<double>(next_id_)));   // < 2^53
  bool edited = false;
  if (auto flags = leaving(dem.particles()); !flags.empty()) {
    dem.remove_particles(flags);
    edited = true;
  }
  const auto cells = planned(dem.particles(), dt_s, fluid);
  // One rank numbers inlet 0's new cells first, then inlet 1's...: each inlet's first id follows the earlier inlets'
  // counts, summed over the ranks (only the rank injecting at an inlet has its cells).
  std::vector<double> count(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) count[k] = static_cast<double>(cells[k].size());
  if (slabs_ != nullptr) {
    MPI_Allreduce(MPI_IN_PLACE, count.data(), static_cast<int>(count.size()), MPI_DOUBLE, MPI_SUM, slabs_->comm());
  }
  std::int64_t first = next_id_;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    std::int64_t id = first;
    for (const NewCell& c : cells[k]) {
      const std::size_t i = dem.insert_particle(c.position_m, c.velocity_m_s, id++);
      dem.particles().inlet_opening()[i] = static_cast<std::int32_t>(k);
      edited = true;
    }
    first += static_cast<std::int64_t>(count[k]);
  }
  next_id_ = first;
  if (slabs_ != nullptr && slabs_->any(edited)) {
    dem.begin_edit();
    // The collective rebuild now, not at the next step: the ghost copies and the plan that sends a ghost's values to
    // its owner index the store as it was before the edit, and the coupling reads them before the next DEM step
    // (a sphere's fluid values went to the new cell's row). One rank has no such copies: its rebuild stays where it was.
    dem.initialize();
  }
}

void OpeningTraffic::exchange(ParticleStore& particles, double dt_s, const FluidAtOpenings& fluid) {
  if (slabs_ != nullptr) throw std::logic_error("OpeningTraffic: a bare store is one rank's; use the DemSystem overload");
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
