// SPDX-License-Identifier: MIT
// The stenosis study's measurement: open-geometry's own (openings, fluxes, checks) plus, every step, the raw sums
// per axial bin the study's statistics need (cells, DI and DI^2, axial velocity, RBC volume, cells whose closure
// inputs left the learned validity box, wall shear rate), and a hemolysis index accumulated along every cell's
// path. The statistics (steady start, means, errors) are study/'s (analysis/ tools).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "unresolved/cases/open_geometry_measurement.hpp"
#include "unresolved/cases/stenosis_study.hpp"
#include "unresolved/coupling/channel_frame.hpp"

namespace hs::unresolved {

/// Columns: open-geometry's (open_geometry_measurement.hpp), then per axial bin I (x from the inlet)
/// xI_cells, xI_di_sum, xI_di_sq_sum, xI_ux_sum (m/s, the cells' axial velocity), xI_rbc_m3, xI_outside_di (cells
/// whose deformation-closure inputs lie outside its validity box), xI_outside_any (outside the box of any closure:
/// drag, lift, deformation) and xI_wall_shear_1_s (sqrt(2 S:S) of the fluid half a cell inside the wall, mean over
/// wall_shear_azimuths points around it at the bin's centre).
///
/// Hemolysis (Giersiepen et al. 1990 power law, linearised for a varying stress as Garon & Farinas 2004, Artif
/// Organs 28:1016): every cell carries I = sum tau^(beta/alpha) dt along its path, tau = mu sqrt(2 S:S) of the
/// plasma at its centre; a cell leaving by an outlet has the index D = C I^alpha (%), kept for the summary.
class StenosisStudyMeasurement final : public CfdDemMeasurement {
 public:
  StenosisStudyMeasurement(const OpenGeometryConfig& c, StenosisStudySpec spec);

  [[nodiscard]] std::string case_type() const override { return base_.case_type(); }
  [[nodiscard]] std::vector<std::string> columns() const override;
  void prepare(CfdDemSolvers& run) override;
  void start(CfdDemSolvers& run) override { base_.start(run); }
  void add_stages(hs::common::TimeLoop& loop, CfdDemSolvers& run) override { base_.add_stages(loop, run); }
  [[nodiscard]] std::vector<double> sample(const CfdDemSolvers& run) override;
  void write_state(hs::common::Checkpoint& cp) const override;
  void read_state(const hs::common::Checkpoint& cp) override;
  /// open-geometry's blocks, with results.study_layout (bins, their centres and fluid volumes, throat, windows,
  /// dt, inlets, whether the plasma volume may change), results.closure_validity and results.hemolysis (the
  /// distribution of D over the cells that left by an outlet).
  [[nodiscard]] nlohmann::json summary(const CfdDemSolvers& run, const std::vector<std::vector<double>>& rows) const override;

 private:
  void accumulate_hemolysis(const CfdDemSolvers& run);

  OpenGeometryMeasurement base_;
  StenosisStudySpec spec_;
  std::vector<std::string> inlets_;
  bool fluid_stores_ = false;
  std::vector<double> bin_fluid_m3_;
  double outlet_x_m_ = 0.0;                        // cells last seen past the tube's middle left by the outlet
  std::unique_ptr<ChannelFrame> frame_;            // the closures' channel frame, as the coupling computes it
  std::unordered_map<std::int64_t, double> exposure_;   // cell id -> sum tau^(beta/alpha) dt
  std::unordered_map<std::int64_t, double> last_x_m_;   // cell id -> x at the last sample
  std::vector<double> left_index_percent_;         // D of each cell that left by the outlet
  std::vector<double> left_exposure_s_;            // and its time in the device
  std::unordered_map<std::int64_t, double> entered_s_;  // cell id -> time first seen
};

}  // namespace hs::unresolved
