// SPDX-License-Identifier: MIT
// The bifurcation study's measurement: open-geometry's own (openings, fluxes, checks) plus, every step, the raw
// counts the study's statistics need: the RBC volume in each bin across each daughter's cut and the DI histogram
// of the cells in each branch. The statistics (steady start, means, errors, S_H) are study/'s (analysis/ tools).
#pragma once

#include <string>
#include <vector>

#include "unresolved/cases/bifurcation_study.hpp"
#include "unresolved/cases/open_geometry_measurement.hpp"

namespace hs::unresolved {

/// Columns: open-geometry's (open_geometry_measurement.hpp), then per daughter NAME (1 then 2) NAME_cut_ht (the
/// slab's RBC volume over its fluid volume) and NAME_cut_rbc_m3_bin_I (I < profile_bins, RBC volume of the cells
/// whose centre is in bin I; w from 0 to 1 along `across`); then per branch NAME (parent first) NAME_cells,
/// NAME_di_sum, NAME_di_below, NAME_di_above, NAME_di_bin_I (I < di_bins over di_range: cells with DI in bin I).
class BifurcationStudyMeasurement final : public CfdDemMeasurement {
 public:
  BifurcationStudyMeasurement(const OpenGeometryConfig& c, BifurcationStudySpec spec);

  [[nodiscard]] std::string case_type() const override { return base_.case_type(); }
  [[nodiscard]] std::vector<std::string> columns() const override;
  void prepare(CfdDemSolvers& run) override { base_.prepare(run); }
  void start(CfdDemSolvers& run) override { base_.start(run); }
  void add_stages(hs::common::TimeLoop& loop, CfdDemSolvers& run) override { base_.add_stages(loop, run); }
  [[nodiscard]] std::vector<double> sample(const CfdDemSolvers& run) override;
  void write_state(hs::common::Checkpoint& cp) const override { base_.write_state(cp); }
  void read_state(const hs::common::Checkpoint& cp) override { base_.read_state(cp); }
  /// open-geometry's blocks, with results.study_layout: what the columns hold (branch names, bins, each bin's fluid
  /// volume, DI range and threshold, the inlets, dt, whether the plasma volume may change).
  [[nodiscard]] nlohmann::json summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const override;

 private:
  OpenGeometryMeasurement base_;
  BifurcationStudySpec spec_;
  std::vector<std::string> inlets_;
  bool fluid_stores_ = false;                       // the pressure equation carries d(eps)/dt ([coupling])
  std::vector<std::vector<double>> bin_fluid_m3_;   // per daughter: fluid volume of each bin of its slab
};

}  // namespace hs::unresolved
