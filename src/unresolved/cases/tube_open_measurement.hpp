// SPDX-License-Identifier: MIT
// What tube-open measures on the CFD-DEM skeleton: cells in and out at the two openings (OpeningTraffic), the
// per-opening counters and fluxes, the tube hematocrit, and the discharge hematocrit at inlet and outlet.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/check_list.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/tube_open.hpp"
#include "unresolved/dem/opening_traffic.hpp"

namespace hs::unresolved {

/// Rows: time_s, cells_present, tube_hematocrit, then per opening (inlet, outlet) NAME_cells_in, NAME_cells_out
/// (since the start), NAME_rbc_flux_m3_s and NAME_fluid_flux_m3_s (in the step, along the flow: into the tube at the
/// inlet, out of it at the outlet), then inlet_debt_cells (RBC volume owed, not yet placed), bookkeeping_error
/// (injected - removed - present: 0 when exact) and pressure_iterations.
///
/// The inflow: the plasma enters with the inlet's parabola (its flux Q_p includes the void fraction at the inlet
/// faces); the inlet is owed Ht_d Q_b dt of RBC volume each step with Q_b = Q_p / (1 - Ht_d), so the inflow's
/// discharge hematocrit Q_rbc / (Q_rbc + Q_p) is Ht_d. Cells enter after the DEM sub-steps (stage cells_in_out),
/// are removed once their centre has crossed the outlet (or, backflow, the inlet) plane.
class TubeOpenMeasurement final : public CfdDemMeasurement {
 public:
  explicit TubeOpenMeasurement(const TubeOpenConfig& c);

  [[nodiscard]] std::string case_type() const override { return "tube-open"; }
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
  void remember_volumes();

  TubeOpenConfig c_;
  std::vector<hs::common::Opening> openings_;
  std::optional<OpeningTraffic> traffic_;
  std::vector<double> last_net_volume_m3_;   // per opening: RBC volume in - out at the last sample
};

/// The case's checks: bookkeeping exact at every step; injected RBC volume within 2% of Ht_d x the inflow over the
/// run (only when it lasts >= 10 transits); at steady state (not --quick) the outlet's discharge hematocrit within 2%
/// of the inlet's and the tube hematocrit below the inlet's discharge hematocrit (Fahraeus).
void check_tube_open(const TubeOpenConfig& c, const nlohmann::json& summary, hs::common::CheckList& checks);

}  // namespace hs::unresolved
