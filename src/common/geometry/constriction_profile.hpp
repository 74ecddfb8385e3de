// SPDX-License-Identifier: MIT
// The smooth (cosine) narrowing shared by the stenosed tube and the stenosed planar channel.
#pragma once

namespace hs::common {

/// Half-width h(s) of a channel of half-width `open_half_width_m` narrowed to `throat_half_width_m` over a
/// constriction of length `length_m` centred at s = 0:
///   h(s) = H - (H - h0)/2 (1 + cos(2 pi s / L))  for |s| < L/2,   h(s) = H otherwise,
/// which is C1-smooth (no sharp corner for the flow or the cells). Used as in Hsieh (2020) and the seed
/// paper (section 3.2: 15 um channel narrowed to 8.5 or 5.5 um; section 4.4 the same x10).
struct ConstrictionProfile {
  double open_half_width_m;
  double throat_half_width_m;
  double length_m;

  [[nodiscard]] double half_width(double s_m) const;
  /// dh/ds, for the first-order distance estimate (h - r) / sqrt(1 + h'^2).
  [[nodiscard]] double slope(double s_m) const;
  /// The same shape `factor` times larger in every length (the seed paper's section 4.4 takes section 3.2's x10).
  [[nodiscard]] ConstrictionProfile scaled(double factor) const {
    return {open_half_width_m * factor, throat_half_width_m * factor, length_m * factor};
  }
  /// Throws std::invalid_argument unless 0 < throat <= open and length > 0.
  void check() const;
};

}  // namespace hs::common
