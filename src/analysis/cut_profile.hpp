// SPDX-License-Identifier: MIT
// Binning across a channel cut: the normalised coordinate w in [0, 1] in equal bins, and the hematocrit of each bin
// from the cell volume counted in it.
#pragma once

#include <vector>

namespace hs::analysis {

/// Bin of w among n equal bins of [0, 1] (w = 1 in the last); -1 outside [0, 1].
[[nodiscard]] int profile_bin(double w, int bins);

/// H_i = rbc_volume_i / fluid_volume_i (0 where fluid_volume_i is 0). pre: equal sizes.
[[nodiscard]] std::vector<double> hematocrit_profile(const std::vector<double>& rbc_volume_m3,
                                                     const std::vector<double>& fluid_volume_m3);

}  // namespace hs::analysis
