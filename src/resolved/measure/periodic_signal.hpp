// SPDX-License-Identifier: MIT
// Period detection and whole-period averaging of a time series (DI, Cd, Cl of a tumbling or tank-treading
// cell), with the period-to-period spread that says how settled the average is.
#pragma once

#include <span>

namespace hs::resolved {

struct PeriodEstimate {
  bool steady = false;       // no oscillation above round-off: the value is constant
  bool periodic = false;     // a clear autocorrelation peak was found
  double period_s = 0.0;
  double correlation = 0.0;  // height of the autocorrelation peak, in [-1, 1]
};

/// Period of a uniformly sampled signal from the first autocorrelation maximum after its first zero
/// crossing, refined by a parabola through the three samples around it. `min_correlation` is the peak
/// height that counts as periodic (0.5 by default: a noisy but clearly repeating signal).
PeriodEstimate detect_period(std::span<const double> signal, double sample_interval_s, double min_correlation = 0.5);

struct PeriodAverage {
  double mean = 0.0;         // mean over the whole periods used
  double spread = 0.0;       // max - min of the per-period means
  int periods = 0;           // whole periods averaged (0 when steady: then the last window is used)
  double period_s = 0.0;
  bool steady = false;
};

/// Averages the last `periods` whole periods of the signal (fewer if the signal is shorter). A steady signal
/// is averaged over its last quarter, with spread = max - min there.
PeriodAverage average_over_periods(std::span<const double> signal, double sample_interval_s, const PeriodEstimate& period,
                                   int periods);

/// Whether a run may stop: `periods` whole periods exist after discarding the first `transient_fraction` of the
/// signal, and the per-period means agree within `relative_spread` of max(|mean|, floor).
bool has_settled(std::span<const double> signal, double sample_interval_s, int periods, double transient_fraction,
                 double relative_spread, double floor = 0.0);

}  // namespace hs::resolved
