// SPDX-License-Identifier: MIT
// Where a simulated time series has settled: the MSER-5 truncation rule (White 1997, Simulation 69:323; White, Cobb
// & Spratt 2000, Proc. Winter Simulation Conf.), and a check that the settled part is steady (its halves agree).
#pragma once

#include <cstddef>
#include <vector>

namespace hs::analysis {

struct SteadyStart {
  bool found = false;      // the truncation lies inside the first half of the series (the rule's validity condition)
  std::size_t start = 0;   // index of the first settled value
};

/// MSER-m: the series in batch means b_j of m values (the remainder at the front dropped); for d = 0 .. n_b / 2,
/// MSER(d) = sum_{j >= d} (b_j - mean_{j >= d})^2 / (n_b - d)^2; the start is m d at the smallest MSER(d). The
/// search stops at half the series (as the rule is used: near the end a few batches look flat by chance); an argmin
/// at that edge means the series is still moving: found = false (start is still that index).
/// Fewer than 4 batches: not found, start 0.
[[nodiscard]] SteadyStart mser_truncation(const std::vector<double>& x, int m = 5);

struct HalvesTest {
  double first_mean = 0.0;
  double second_mean = 0.0;
  double combined_error = 0.0;   // sqrt(se_1^2 + se_2^2), each by batch means
  bool agree = false;            // |second - first| <= max(k combined_error, relative_floor max(|first|, |second|))
};

/// Splits x[start, end) into two halves, each by batch means (`batches` per half), and compares their means within
/// k standard errors, or within relative_floor of their size (a nearly noiseless series, e.g. a flow rate, whose
/// standard error alone would flag a drift of 1e-6). A constant series agrees; a ramp whose rise over the window is
/// large against its noise and the floor does not. Too short (fewer than 2 batches per half): agree = false.
[[nodiscard]] HalvesTest halves_agree(const std::vector<double>& x, std::size_t start, double k = 3.0, int batches = 5,
                                      double relative_floor = 0.0);

}  // namespace hs::analysis
