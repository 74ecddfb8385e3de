// SPDX-License-Identifier: MIT
// What open-geometry measures on the CFD-DEM skeleton: cells in and out at every opening (OpeningTraffic), the
// per-opening counters and fluxes, the domain's hematocrit and mean DI, the fluid's balance, and the checks.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/check_list.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/dem/opening_traffic.hpp"

namespace hs::unresolved {

/// Rows: time_s, cells_present, domain_hematocrit (RBC volume over the domain's fluid volume), mean_di (of the cells
/// present, from the deformation closure), plasma_volume_m3 (sum of eps over the fluid volume), then per opening
/// (names sorted) NAME_cells_in, NAME_cells_out (since the start), NAME_rbc_flux_m3_s and NAME_fluid_flux_m3_s (in the
/// step, along the flow: into the domain at an inlet, out of it at an outlet), then inlet_debt_cells (RBC volume owed
/// by all inlets, not yet placed, in cells), bookkeeping_error (injected - removed - present: 0 when exact) and
/// pressure_iterations.
///
/// Each inlet k is owed Ht_d,k Q_b,k dt of RBC volume a step, Q_b,k = Q_p,k / (1 - Ht_d,k) with Q_p,k the plasma flux
/// through its faces as the solver counts it, so its inflow's discharge hematocrit is Ht_d,k (as tube-open).
/// On slabs every value is the whole domain's (summed over the ranks; sample and summary are collective).
class OpenGeometryMeasurement final : public CfdDemMeasurement {
 public:
  /// `case_type` names the case in checkpoints (tube-open runs on this measurement too).
  explicit OpenGeometryMeasurement(const OpenGeometryConfig& c, std::string case_type = "open-geometry");

  [[nodiscard]] std::string case_type() const override { return case_type_; }
  [[nodiscard]] std::vector<std::string> columns() const override;
  void prepare(CfdDemSolvers& run) override;
  void start(CfdDemSolvers& run) override;
  void add_stages(hs::common::TimeLoop& loop, CfdDemSolvers& run) override;
  [[nodiscard]] std::vector<double> sample(const CfdDemSolvers& run) override;
  void write_state(hs::common::Checkpoint& cp) const override;
  void read_state(const hs::common::Checkpoint& cp) override;
  [[nodiscard]] nlohmann::json summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const override;

 private:
  void exchange_cells(CfdDemSolvers& run);
  void remember_volumes(const std::vector<OpeningCounters>& counters);   // every rank's, summed
  [[nodiscard]] nlohmann::json opening_summary(const std::vector<std::vector<double>>& rows, long first,
                                               const std::vector<OpeningCounters>& counters) const;

  OpenGeometryConfig c_;
  std::string case_type_;
  std::vector<hs::common::Opening> openings_;
  std::optional<OpeningTraffic> traffic_;
  std::vector<double> last_net_volume_m3_;   // per opening: RBC volume in - out at the last sample
  double domain_volume_m3_ = 0.0;            // fluid volume of the grid (geometry only)
};

/// The case's checks: bookkeeping exact at every step; injected RBC volume within 2% of Ht_d x the inflow (only after
/// >= 10 residence times); at the end of a full run (not --quick) the fluid's balance over the averaging window within
/// 0.1% of the inflow and the domain hematocrit steady (its two averaging halves within 2% of each other).
/// `results` is summary.json's "results" block.
void check_open_geometry(const OpenGeometryConfig& c, const nlohmann::json& results, hs::common::CheckList& checks);

}  // namespace hs::unresolved
