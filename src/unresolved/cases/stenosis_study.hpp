// SPDX-License-Identifier: MIT
// The stenosis study's measurement settings ([study] of an open-geometry case on a "stenosed-tube" shape) and its
// geometry: equal bins along the tube's axis x, each bin's fluid volume, the windows before and after the
// constriction (docs/stenosis.md).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "common/config/config_file.hpp"
#include "common/geometry/stenosed_tube.hpp"

namespace hs::unresolved {

/// Giersiepen et al. 1990 (Int J Artif Organs 13:300-306), fitted on Couette-viscometer hemolysis of human blood:
/// released hemoglobin dHb/Hb (%) = C t^alpha tau^beta, t in s, tau the shear stress in Pa.
struct HemolysisPowerLaw {
  double c_percent = 3.62e-5;
  double alpha = 0.785;   // exponent of the exposure time
  double beta = 2.416;    // exponent of the stress
};

struct StenosisStudySpec {
  hs::common::StenosedTubeSpec tube;   // the shape's own spec (axis along +x from start_m)
  int x_bins = 1;                      // equal bins over [x_lo_m, x_hi_m]: the tube's length
  double x_lo_m = 0.0;
  double x_hi_m = 0.0;
  std::array<double, 2> upstream_window_m{};     // [x0, x1] of <DI> upstream of the constriction
  std::array<double, 2> downstream_window_m{};   // [x0, x1] of <DI> downstream of it
  int wall_shear_azimuths = 8;                   // points around the wall at which the shear rate is read per bin
  HemolysisPowerLaw hemolysis{};

  [[nodiscard]] double bin_width_m() const { return (x_hi_m - x_lo_m) / x_bins; }
  [[nodiscard]] double bin_centre_m(int i) const { return x_lo_m + (i + 0.5) * bin_width_m(); }
  /// Bin of x, or -1 outside [x_lo_m, x_hi_m] (x = x_hi_m falls in the last bin).
  [[nodiscard]] int bin_of(double x_m) const;
  [[nodiscard]] double throat_x_m() const { return tube.start_m.x + tube.constriction_centre_m; }
  /// Wall radius at axial position x (the shape's ConstrictionProfile).
  [[nodiscard]] double radius_at(double x_m) const;
  /// Fluid volume of each bin, pi r(x)^2 integrated over it (Simpson's rule, 64 panels a bin: the cosine's error
  /// is below 1e-8 of the volume).
  [[nodiscard]] std::vector<double> bin_fluid_m3() const;
};

/// Reads [study] when the case has one (else nothing): x_bins, upstream_window_m and downstream_window_m ([x0, x1],
/// m, inside the tube, x0 < x1), wall_shear_azimuths (optional, 8). ConfigError (exit 2) naming file, key and value
/// when the shape is not a stenosed tube along +x, a window lies outside the tube or is empty.
[[nodiscard]] std::optional<StenosisStudySpec> parse_stenosis_study(hs::common::ConfigSection root, const hs::common::Shape& shape);

}  // namespace hs::unresolved
