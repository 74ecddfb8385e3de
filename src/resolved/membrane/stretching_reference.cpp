// SPDX-License-Identifier: MIT
// Reading the Mills et al. 2004 stretching band.
#include "resolved/membrane/stretching_reference.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/csv_writer.hpp"

namespace hs::resolved {

std::vector<StretchingBandPoint> read_stretching_band(const std::filesystem::path& csv) {
  const hs::common::CsvTable t = hs::common::read_csv(csv);
  const char* names[] = {"force_pN_digitized", "axial_lower_um", "axial_mid_um", "axial_upper_um",
                         "transverse_lower_um", "transverse_mid_um", "transverse_upper_um"};
  int col[7];
  for (int k = 0; k < 7; ++k) {
    col[k] = t.column_index(names[k]);
    if (col[k] < 0) throw hs::common::ConfigError(fmt::format("{}: column '{}' is missing", csv.string(), names[k]));
  }
  std::vector<StretchingBandPoint> band;
  for (const auto& r : t.rows) {
    band.push_back({.force_N = r[col[0]] * 1e-12,
                    .axial_lower_m = r[col[1]] * 1e-6, .axial_mid_m = r[col[2]] * 1e-6, .axial_upper_m = r[col[3]] * 1e-6,
                    .transverse_lower_m = r[col[4]] * 1e-6, .transverse_mid_m = r[col[5]] * 1e-6,
                    .transverse_upper_m = r[col[6]] * 1e-6});
  }
  return band;
}

std::filesystem::path default_stretching_band_csv() {
  return std::filesystem::path(HS_MEMBRANE_DATA_DIR) / "mills2004_rbc_stretch_experiment.csv";
}

}  // namespace hs::resolved
