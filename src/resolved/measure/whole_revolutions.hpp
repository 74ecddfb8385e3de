// SPDX-License-Identifier: MIT
// The tank-treading membrane's revolutions, counted back from the end of a run: their periods say whether the motion
// has settled into a periodic state, and their window is the one to average over (a swinging cell's inclination and
// DI repeat twice per revolution, so means over whole revolutions carry no partial-swing bias).
#pragma once

#include <span>
#include <vector>

namespace hs::resolved {

struct WholeRevolutions {
  std::vector<double> periods_s;   // the marker's whole revolutions, the last one first
  std::vector<double> ends_s;      // their ends, the last first: revolution k spans [ends_s[k + 1], ends_s[k]]
  double window_start_s = 0.0;     // start of the earliest whole revolution counted
  double window_end_s = 0.0;

  /// Mean rate over all the whole revolutions, rad/s; 0 without one.
  [[nodiscard]] double rate_rad_s() const;
  /// Whether the revolutions show no trend: at least four, and the last two together took the same time as the two
  /// before them within `tolerance` (relative). Pairs, not single revolutions: a single revolution's period jitters by a
  /// few per cent without a trend (the marker is one vertex of a discrete membrane crossing a lattice).
  [[nodiscard]] bool settled(double tolerance) const;
  /// settled(tolerance), and the mean of `value` (sampled at `time_s`) over the last two revolutions equal to its mean
  /// over the two before within `tolerance` (relative): a swinging cell whose periods repeat can still change its shape
  /// slowly (measured: DI 0.36 -> 0.24 over ~10 revolutions at 10.7 mPa s, Ca 2.04, each pair's periods within 2 %).
  [[nodiscard]] bool settled(double tolerance, std::span<const double> time_s, std::span<const double> value) const;
};

/// Whole revolutions of the unwrapped marker phase `phase_rad` (sampled at `time_s`), counted backwards from the last
/// sample and only over samples from index `from` on (the part after the release transient). A revolution ends where the
/// phase has moved by 2 pi from the end of the next one (linear interpolation between samples), whichever the sense.
WholeRevolutions whole_revolutions(std::span<const double> time_s, std::span<const double> phase_rad, std::size_t from);

/// Keller & Skalak (1982, JFM 120:27): a membrane of axes a1 >= a2 in the shear plane tank-treads at most at
/// gamma_dot a1 a2 / (a1^2 + a2^2); here a1 / a2 = (1 + DI) / (1 - DI) from the deformation index DI = (a1 - a2) / (a1 + a2).
double keller_skalak_bound(double shear_rate_1_s, double deformation_index);

}  // namespace hs::resolved
