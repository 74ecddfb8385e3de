// SPDX-License-Identifier: MIT
// The mean of a correlated time series and its standard error by batch means (e.g. Law & Kelton, Simulation
// Modeling and Analysis, ch. 9): contiguous batches long against the correlation time are nearly independent.
#pragma once

#include <vector>

namespace hs::common {

struct MeanWithError {
  double mean = 0.0;
  double standard_error = 0.0;   // sd of the batch means (n - 1) / sqrt(batches)
  int batches = 0;
};

/// Splits x[first, end) into `batches` contiguous batches of equal length (the remainder dropped at the front, the
/// end of a run being the better-settled part) and returns the mean of the batch means and its standard error.
/// std::invalid_argument when batches < 2 or fewer values than batches.
[[nodiscard]] MeanWithError batch_means(const std::vector<double>& x, int batches, std::size_t first = 0);

/// The same over a series of vectors taken component-wise (a profile per sample): one MeanWithError per component.
[[nodiscard]] std::vector<MeanWithError> batch_means(const std::vector<std::vector<double>>& x, int batches,
                                                     std::size_t first = 0);

}  // namespace hs::common
