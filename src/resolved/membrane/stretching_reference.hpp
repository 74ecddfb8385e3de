// SPDX-License-Identifier: MIT
// The Mills et al. 2004 optical-tweezers band (axial and transverse diameters vs force) and band checks.
#pragma once

#include <filesystem>
#include <vector>

namespace hs::resolved {

struct StretchingBandPoint {
  double force_N = 0.0;
  double axial_lower_m = 0.0, axial_mid_m = 0.0, axial_upper_m = 0.0;
  double transverse_lower_m = 0.0, transverse_mid_m = 0.0, transverse_upper_m = 0.0;

  [[nodiscard]] bool axial_inside(double d_m) const { return d_m >= axial_lower_m && d_m <= axial_upper_m; }
  [[nodiscard]] bool transverse_inside(double d_m) const { return d_m >= transverse_lower_m && d_m <= transverse_upper_m; }
};

/// Reads data/reference/mills2004_rbc_stretch_experiment.csv (force in pN, diameters in um; converted to SI).
/// Throws ConfigError if the file or a column is missing.
[[nodiscard]] std::vector<StretchingBandPoint> read_stretching_band(const std::filesystem::path& csv);
/// The copy committed with the source tree (absolute path fixed at build time).
[[nodiscard]] std::filesystem::path default_stretching_band_csv();

}  // namespace hs::resolved
