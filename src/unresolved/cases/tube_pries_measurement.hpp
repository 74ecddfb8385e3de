// SPDX-License-Identifier: MIT
// What tube-pries measures on the CFD-DEM skeleton: the flow rates of blood and cells through the periodic tube,
// Ht_d = Q_rbc / Q_blood and mu_rel = Q_plasma / Q_blood against a plasma-only run of the same grid.
#pragma once

#include <string>
#include <vector>

#include "unresolved/cases/cfd_dem_case.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace hs::unresolved {

/// The periodic tube along z of the case: shape, grid (periodic z), DEM domain, fluid drive and coupling.
[[nodiscard]] CfdDemSetup tube_pries_setup(const TubePriesConfig& c);

/// CFD steps of the shortest run (end_time_s) and of the longest (max_end_time_s, not below the shortest).
[[nodiscard]] long min_steps_of(const TubePriesConfig& c);
[[nodiscard]] long max_steps_of(const TubePriesConfig& c);
/// Steps between two steady-state checks past end_time_s: a tenth of the shortest run.
[[nodiscard]] long steady_check_every_steps(const TubePriesConfig& c);

/// The result of a run from its summary (Ht_d and mu_rel; the Pries fields are left 0 for the validation side).
[[nodiscard]] TubePriesResult tube_pries_result(const nlohmann::json& summary);

/// Rows: time_s, flow_rate_blood_m3_s, flow_rate_rbc_m3_s, discharge_hematocrit, pressure_iterations. Checkpointed
/// beyond the rows: the insertion's achieved Ht_c and cell count (under "insertion", as before the skeleton).
class TubePriesMeasurement final : public CfdDemMeasurement {
 public:
  explicit TubePriesMeasurement(const TubePriesConfig& c) : c_(c) {}

  [[nodiscard]] std::string case_type() const override { return "tube-pries"; }
  [[nodiscard]] std::vector<std::string> columns() const override;
  /// Q_plasma: the same grid and pressure gradient without cells, run to its steady state (at most the same end time).
  void prepare(CfdDemSolvers& run) override;
  /// Cells at Ht_c, at rest, in fluid at rest; u_r+'s mean velocity from Q_plasma.
  void start(CfdDemSolvers& run) override;
  [[nodiscard]] std::vector<double> sample(const CfdDemSolvers& run) override;
  /// Past end_time_s, at every tenth of it: steady here and at the check before (steady_after), so one quiet
  /// stretch of a drifting series does not end the run.
  [[nodiscard]] bool finished(const std::vector<std::vector<double>>& rows) const override;
  void write_state(hs::common::Checkpoint& cp) const override;
  void read_state(const hs::common::Checkpoint& cp) override;
  /// Ht_d and Q averaged over the last (1 - average_from_fraction) of the rows, steadiness, groups, model names.
  [[nodiscard]] nlohmann::json summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const override;

 private:
  TubePriesConfig c_;
  double q_plasma_m3_s_ = 0.0;
  double ht_achieved_ = 0.0;
  double rbc_count_ = 0.0;
};

}  // namespace hs::unresolved
