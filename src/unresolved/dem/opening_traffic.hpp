// SPDX-License-Identifier: MIT
// Cells in and out of a flow geometry: injection at its inlets, removal at its openings, per-opening counters.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/opening.hpp"
#include "common/io/checkpoint.hpp"
#include "unresolved/dem/cell_injector.hpp"
#include "unresolved/dem/dem_slabs.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/dem/particle_params.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// What went through one opening since the start (integer counts exact; volumes are sums of sphere volumes).
struct OpeningCounters {
  std::string name;
  hs::common::OpeningKind kind = hs::common::OpeningKind::inlet;
  std::int64_t cells_in = 0;
  std::int64_t cells_out = 0;
  double rbc_volume_in_m3 = 0.0;
  double rbc_volume_out_m3 = 0.0;
  double fluid_volume_in_m3 = 0.0;   // sum of Q dt handed in for an inlet (what the injection was owed against)
};

struct OpeningTrafficSpec {
  std::vector<hs::common::Opening> openings;     // checked with check_openings
  std::vector<double> discharge_hematocrit;      // one per opening (ignored for outlets)
  ParticleParams particles;                      // size and density of the injected cells
  std::uint64_t seed;                            // inlet k draws from seed + k
  double slab_thickness_m = 0.0;                 // see InjectionSpec
};

/// The fluid at the openings during the step just taken.
struct FluidAtOpenings {
  std::vector<double> flow_rate_m3_s;   // into the fluid, one per opening (only inlets are read)
  VelocityField velocity_m_s;
};

/// After each DEM step: first every owned particle whose centre has crossed an opening's plane (height > 0)
/// within its disc (lateral <= R + r) is removed and counted there (at an inlet too: backflow), then each inlet
/// injects what it is owed (CellInjector). Ids of new cells continue above the largest id ever seen, so they
/// never repeat; each new cell records the index of its inlet in ParticleStore::inlet_opening(). Bookkeeping: cells_injected() + (particles at the start) = cells_removed() + n_owned(), exactly.
class OpeningTraffic {
 public:
  /// ConfigError (naming the opening and key) for a bad opening or hematocrit. `slabs` (the DEM's, may be null):
  /// each rank removes its own particles, and an inlet injects on the rank whose slab holds its centre, which must
  /// face along z and hold the injection region and a cut-off beyond it (so a new cell needs no ghost before the next
  /// rebuild, and the cells near the region are all that rank's); ConfigError on every rank otherwise.
  OpeningTraffic(const OpeningTrafficSpec& spec, const hs::common::Shape& shape, const Domain& domain,
                 const DemSlabs* slabs = nullptr);

  /// On a DemSystem: contact springs and forces of the particles that stay are kept (DemSystem::remove_particles,
  /// insert_particle). On slabs collective: new cells get the ids one rank would give them (inlet by inlet, above
  /// the largest id on any rank), and every rank begins an edit when one does.
  void exchange(DemSystem& dem, double dt_s, const FluidAtOpenings& fluid);
  /// On a bare store (particles moved by a prescribed velocity, no contacts): the same removal and injection (one
  /// rank only).
  void exchange(ParticleStore& particles, double dt_s, const FluidAtOpenings& fluid);

  /// This rank's counts (on slabs: the cells it removed and injected).
  [[nodiscard]] const std::vector<OpeningCounters>& counters() const { return counters_; }
  /// Every rank's counts summed (collective on slabs; counters() on one rank).
  [[nodiscard]] std::vector<OpeningCounters> summed_counters() const;
  [[nodiscard]] std::int64_t cells_injected() const;
  [[nodiscard]] std::int64_t cells_removed() const;
  /// The injector of opening `index` (null for an outlet, and on slabs for an inlet another rank injects at), e.g.
  /// for its debt.
  [[nodiscard]] const CellInjector* injector(std::size_t index) const;

  /// Restart (opening_traffic_checkpoint.cpp): counters, each inlet's debt and random stream and the next id, under
  /// names starting with `prefix`. read_state() throws ConfigError when the checkpoint has other openings.
  void write_state(hs::common::Checkpoint& cp, const std::string& prefix) const;
  void read_state(const hs::common::Checkpoint& cp, const std::string& prefix);

 private:
  /// Slabs: which inlets this rank injects at; ConfigError on every rank when one does not fit its slab.
  void place_inlets(const OpeningTrafficSpec& spec);
  /// Flags the owned particles leaving, counts them; returns the flags (empty when none leaves).
  std::vector<bool> leaving(const ParticleStore& particles);
  std::vector<std::vector<NewCell>> planned(const ParticleStore& particles, double dt_s, const FluidAtOpenings& fluid);
  void note_ids(const ParticleStore& particles);

  std::vector<hs::common::Opening> openings_;
  ParticleParams params_;
  std::vector<std::optional<CellInjector>> injectors_;
  const DemSlabs* slabs_;
  std::vector<bool> injects_here_;   // per opening: an inlet whose cells this rank places
  std::vector<OpeningCounters> counters_;
  std::int64_t next_id_ = 0;
};

}  // namespace hs::unresolved
