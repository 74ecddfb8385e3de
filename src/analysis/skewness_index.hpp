// SPDX-License-Identifier: MIT
// The hematocrit skewness index of a profile across a channel cut (Sherwood et al. 2014, PLoS ONE 9:e100473;
// Stathoulopoulos et al. 2024, Sci Rep 14; the seed paper's section 4.3): how far H(w) is from its mirror image.
#pragma once

#include <vector>

namespace hs::analysis {

/// S_H = int_0^1 |H(w) - H(1 - w)| dw / int_0^1 H(w) dw, w in [0, 1] the normalised coordinate across the cut, for a
/// profile given as the means of n equal bins of w (bin i covers [i/n, (i+1)/n]); the integrals by the midpoint rule,
/// so S_H = sum_i |H_i - H_{n-1-i}| / sum_i H_i. 0 for any symmetric profile; for H = H0 (1 + a (2w - 1)) exactly |a|
/// at an even n, |a| (1 - 1/n^2) at an odd n (the kink of |2w - 1| inside the middle bin); 2 with all cells on one
/// half. 0 for an empty profile (sum 0). std::invalid_argument for an H_i < 0.
[[nodiscard]] double skewness_index(const std::vector<double>& binned_profile);

}  // namespace hs::analysis
